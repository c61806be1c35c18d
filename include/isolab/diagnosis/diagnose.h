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
// larger model's residual, samples over its integrated correlation time (discrepancy.h):
// filtered (band-limited) noise is worth far fewer independent samples than it has, and counting
// them all would let a component that fits a little of it through; oversampled data have more
// samples and a longer correlation time alike, so the count does not change with the rate. A
// margin of 10 is "very strong" evidence (Kass & Raftery 1995).
//
// Two guards beyond BIC. A refit whose added component cancels one already in the model (their
// forces oppose and mostly cancel: identifiability.h) is refused, however much it lowers BIC:
// two large parts trading against each other are not an effect. And after the last step the
// residual is judged (residual.h): when it is not noise, the diagnosis says so, whatever was
// added before.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "isolab/diagnosis/detectors.h"
#include "isolab/diagnosis/residual.h"
#include "isolab/identification/fit.h"
#include "isolab/identification/identifiability.h"

namespace isolab::diagnosis {

struct FittedModel {
  std::vector<identification::ComponentSpec> components;
  identification::FitResult fit;
  int parameters = 0;              // fitted: shape coordinates and stiffnesses
  double effective_samples = 0.0;  // of its residual (EffectiveSamples)
  double bic = 0.0;                // at its own effective sample count
  // Components the fit gave no stiffness at all, dropped from the model (their forces were zero,
  // so e^2 is unchanged): one note each.
  std::vector<std::string> dropped;
};

// An effect considered at a step: its evidence and, when the evidence supported it, the refit.
struct Candidate {
  Evidence evidence;
  bool refitted = false;
  double e2 = 0.0;  // after adding the effect's component and refitting
  // BIC of the refit, and of the model before it, both at the refit's effective sample count.
  double bic = 0.0, bic_current = 0.0;
  int parameters = 0;
  // Why a refit that lowered BIC enough was still refused: its added component cancels one
  // already there (identifiability.h), so the gain is two large parts trading, not an effect; or
  // it closed less than min_closure of the excess over the noise floor.
  std::string refused{};
  double Gain() const { return bic_current - bic; }
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

enum class StopReason {
  kAtNoiseFloor,  // e^2 within noise_margin of the noise floor
  kMaxSteps,      // max_steps effects added
  kNoEvidence,    // no detector reached its threshold
  kNoBicGain,     // no supported candidate lowered BIC by bic_margin
  kRefused,       // the candidates that lowered BIC enough were refused (cancelling components,
                  // or too little of the excess over the noise floor closed)
};

// "at_noise_floor", "max_steps", ... as reports write them.
std::string_view StopReasonName(StopReason reason);

struct Diagnosis {
  long samples = 0;
  // The e^2 that the measurement noise alone leaves (NoiseFloor), from each test's noise: the
  // lower of the estimates from the data's force and from the final model's residual
  // (discrepancy.h), so the loops' harmonic lines the model takes out cannot inflate it.
  double noise_floor = 0.0;
  std::vector<NoiseEstimate> noise;  // per test
  FittedModel base;
  std::vector<DiagnosisStep> steps;
  FittedModel final_model;
  std::vector<Candidate> last_candidates;  // the round that ended the search
  StopReason stop = StopReason::kNoEvidence;
  std::string stop_reason;                          // one sentence with the numbers
  ResidualVerdict verdict;                          // on the final model's residual
  identification::Identifiability identifiability;  // of the final model
  double seconds = 0.0;
};

struct DiagnoseOptions {
  unsigned seed = 1;    // a fixed seed reproduces the diagnosis, on any machine
  long budget = 12000;  // model evaluations per fit (CMA-ES and polish); >= 100
  int threads = 0;      // as identification::FitOptions::threads: speed only
  // As identification::FitOptions::spread: each fit's islands on other processes too.
  const identification::TaskSpread* spread = nullptr;
  double bic_margin = 10.0;   // decrease of BIC an added effect must reach; > 0
  double noise_margin = 1.2;  // stop once e^2 <= noise_margin x the noise floor; >= 1
  // Candidates whose BIC gains differ by less than this are equal: the smaller model (fewer
  // parameters) wins. >= 0.
  double equal_bic = 2.0;
  // The share of the excess of e^2 over the noise floor a step must close to name its effect;
  // [0, 1). A component that fits a sliver of a residual it cannot explain lowers BIC on a large
  // data set all the same (a hardening spring took 4 % of a Bouc-Wen device's residual), and
  // naming it would dress a catalogue effect up as the explanation.
  double min_closure = 0.2;
  int max_steps = 4;  // effects added at most; 0 to 6 (the catalogue's size)
  std::function<void(const std::string&)> progress;  // one line per fit

  // Throws InvalidParameter naming the first field out of range.
  void Validate() const;
};

// Throws std::invalid_argument for a base that cannot be fitted (no components, Bouc-Wen) and
// InvalidParameter for options out of range (DiagnoseOptions::Validate).
Diagnosis Diagnose(std::vector<identification::ComponentSpec> base,
                   const identification::FitData& data, const DiagnoseOptions& options);

double InformationCriterion(double e2, double samples, int parameters);

// The fitted model as an assembly (for reports: loops, residuals).
hysteresis::ParallelAssembly AssemblyOf(const FittedModel& model,
                                        const identification::FitData& data);

}  // namespace isolab::diagnosis
