// The discrepancy workflow: fit the base model to the measured cycles, read where it misses
// (detectors.h), try each effect the evidence supports by adding its component (effects.h) and
// refitting, keep the one the Bayesian information criterion prefers, and repeat until no
// candidate passes. An effect is named only when (1) its detector's statistic reaches the
// threshold, (2) the refitted model lowers BIC by a decisive margin, and (3) the current model
// still misses by more than the measurement noise explains.
//
// BIC = n ln(e^2 / n) + p ln n (Schwarz 1978), with p the fitted parameters (shape coordinates
// and stiffnesses). e^2 weights each test by its own force norm, which is the Gaussian
// likelihood when each test's noise scales with its RMS force and tests have equal sample
// counts, as in a load cell of fixed relative accuracy. n is the effective sample count of the
// larger model's residual, n_samples (1 - rho) / (1 + rho) with rho its lag-1 autocorrelation:
// filtered (band-limited) noise is worth far fewer independent samples than it has, and counting
// them all would let a component that fits a little of it through. A margin of 10 is "very
// strong" evidence (Kass & Raftery 1995).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "isolab/diagnosis/detectors.h"
#include "isolab/identification/fit.h"

namespace isolab::diagnosis {

struct FittedModel {
  std::vector<identification::ComponentSpec> components;
  identification::FitResult fit;
  int parameters = 0;              // fitted: shape coordinates and stiffnesses
  double effective_samples = 0.0;  // of its residual (EffectiveSamples)
  double bic = 0.0;                // at its own effective sample count
};

// An effect considered at a step: its evidence and, when the evidence supported it, the refit.
struct Candidate {
  Evidence evidence;
  bool refitted = false;
  double e2 = 0.0;  // after adding the effect's component and refitting
  // BIC of the refit, and of the model before it, both at the refit's effective sample count.
  double bic = 0.0, bic_current = 0.0;
  int parameters = 0;
};

struct DiagnosisStep {
  Effect effect = Effect::kRateDependence;
  Evidence evidence;
  double e2_before = 0.0, e2_after = 0.0;
  double bic_before = 0.0, bic_after = 0.0;
  identification::ComponentSpec added;
  std::vector<double> added_parameters;  // mathematical (ParameterKeys order)
  std::vector<Candidate> candidates;     // every effect considered, strongest evidence first
};

struct Diagnosis {
  long samples = 0;
  double noise_floor = 0.0;  // e^2 that the measurement noise alone leaves
  FittedModel base;
  std::vector<DiagnosisStep> steps;
  FittedModel final_model;
  std::vector<Candidate> last_candidates;  // the round that ended the search
  std::string stop_reason;
  double seconds = 0.0;
};

struct DiagnoseOptions {
  unsigned seed = 1;
  long budget = 12000;        // model evaluations per fit (CMA-ES and polish); >= 100
  double bic_margin = 10.0;   // decrease of BIC an added effect must reach; > 0
  double noise_margin = 1.2;  // stop once e^2 <= noise_margin x the noise floor; >= 1
  int max_steps = 4;          // effects added at most
  std::function<void(const std::string&)> progress;  // one line per fit
};

// Throws std::invalid_argument for a base that cannot be fitted (no components, Bouc-Wen) or
// options out of range.
Diagnosis Diagnose(std::vector<identification::ComponentSpec> base,
                   const identification::FitData& data, const DiagnoseOptions& options);

double InformationCriterion(double e2, double samples, int parameters);

// The fitted model as an assembly (for reports: loops, residuals).
hysteresis::ParallelAssembly AssemblyOf(const FittedModel& model,
                                        const identification::FitData& data);

}  // namespace isolab::diagnosis
