// Identification of an assembly's parameters from cyclic tests (Markou & Manolis 2016, Sec. 5):
// minimise the paper's error
//   e^2 = sum_i <F0_i - F_i, F0_i - F_i> / <F0_i, F0_i>
// over tests i (F0 measured, F modelled; inner products over the fitted samples), the model
// driven by each test's measured displacement history: from rest, or, when the tests are one
// specimen, from the state the previous test left. The search is pagmo2's
// CMA-ES over the shape coordinates of ModelParametrisation (the stiffness amplitudes follow from
// a sign-constrained linear least-squares solve at every point), several islands in parallel
// threads, each with its own seed and IPOP restarts, then pagmo's compass search from the best
// point. A fixed seed reproduces a fit exactly.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <span>
#include <vector>

#include "isolab/identification/cyclic_data.h"
#include "isolab/identification/parametrisation.h"

namespace isolab::identification {

// The tests and, for each, the spans of samples that enter the error.
struct FitData {
  std::vector<CyclicTestData> tests;
  std::vector<std::vector<CycleSpan>> fitted;  // per test
  bool one_specimen = false;  // tests continue one specimen, in order (cyclic_data.h)
};

// The samples to fit: the whole cycles `cycles` (1-based) of every test (as the paper fits the
// third cycle of each sinusoidal test, leaving out the virgin loading), or, when empty, the whole
// history of every test: any displacement history is test data. Throws std::invalid_argument
// naming the test that lacks a requested cycle.
FitData SelectCycles(std::vector<CyclicTestData> tests, const std::vector<int>& cycles,
                     bool one_specimen = false);

DataScales ScalesOf(const FitData& data);

struct FitError {
  double total = 0.0;            // the paper's e^2, the sum of per_test
  std::vector<double> per_test;  // each test's term
};

FitError ComputeFitError(const hysteresis::ParallelAssembly& assembly, const FitData& data);

// The best amplitudes for the shape point x (signs as the model requires) and the e^2 they give.
struct AmplitudeSolution {
  Eigen::VectorXd amplitudes;
  double error = 0.0;  // e^2 from the normal equations
};
AmplitudeSolution SolveAmplitudes(const ModelParametrisation& model, std::span<const double> x,
                                  const FitData& data);

struct FitProgress {
  long evaluations = 0;
  int generation = 0;  // CMA-ES generations of the leading island
  double best = 0.0;   // best e^2 so far
  bool polishing = false;
};

struct FitOptions {
  unsigned seed = 1;
  long budget = 60000;        // model evaluations over all islands, CMA-ES and polish; >= 100
  int islands = 0;            // parallel CMA-ES islands; 0: one per hardware thread (at least 2)
  double polish_share = 0.1;  // share of the budget for the compass-search polish; [0, 1)
  std::function<void(const FitProgress&)> progress;  // called every few generations
};

struct FitResult {
  std::vector<double> point;  // shape point, in the unit cube
  Eigen::VectorXd amplitudes;
  std::vector<std::vector<double>> mathematical;  // per component
  FitError error;                                 // of the fitted assembly, by simulation
  long evaluations = 0;
  int restarts = 0;
  double seconds = 0.0;
};

FitResult Fit(const ModelParametrisation& model, const FitData& data, const FitOptions& options);

}  // namespace isolab::identification
