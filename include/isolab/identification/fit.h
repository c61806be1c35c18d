// Identification of an assembly's parameters from cyclic tests (Markou & Manolis 2016, Sec. 5):
// minimise the paper's error
//   e^2 = sum_i <F0_i - F_i, F0_i - F_i> / <F0_i, F0_i>
// over tests i (F0 measured, F modelled; inner products over the fitted samples), the model
// driven by each test's measured displacement history: from rest, or, when the tests are one
// specimen, from the state the previous test left. The search is pagmo2's
// CMA-ES over the shape coordinates of ModelParametrisation (the stiffness amplitudes follow from
// a sign-constrained linear least-squares solve at every point), a fixed number of islands, each
// with its own seed and IPOP restarts, then pagmo's compass search from the best point.
//
// The same answer on every machine: the number of islands is an option with a fixed default,
// never the core count, because the budget is split across islands and so their number shapes
// the search. Threads only run islands side by side and share the work of one evaluation (each
// component's force through each test goes to its own column, summed afterwards in one order),
// so a fixed seed reproduces a fit to the last digit whatever the thread count.
#pragma once

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "isolab/identification/cyclic_data.h"
#include "isolab/identification/parametrisation.h"
#include "isolab/identification/unit_cube_search.h"

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

// The range of the fitted samples of every test (IdentifiedRange): the half-cycles' reversals of
// the tests' segmentation that lie within a fitted span are counted.
IdentifiedRange RangeOf(const FitData& data);

struct FitError {
  double total = 0.0;            // the paper's e^2, the sum of per_test
  std::vector<double> per_test;  // each test's term

  // Mean over tests: what one test's e^2 typically is. The sum grows with the number of tests,
  // so "99.9 % over 10 tests" reads as a useless model where each test is missed by 10 %.
  double Mean() const { return per_test.empty() ? 0.0 : total / double(per_test.size()); }
};

FitError ComputeFitError(const hysteresis::ParallelAssembly& assembly, const FitData& data);

// The best amplitudes for the shape point x (signs as the model requires) and the e^2 they give.
struct AmplitudeSolution {
  Eigen::VectorXd amplitudes;
  double error = 0.0;  // e^2 from the normal equations
};
// `threads` share the work of the basis (ModelParametrisation::Basis); the result does not
// depend on it.
AmplitudeSolution SolveAmplitudes(const ModelParametrisation& model, std::span<const double> x,
                                  const FitData& data, int threads = 1);

struct FitResult {
  std::vector<double> point;  // shape point, in the unit cube
  Eigen::VectorXd amplitudes;
  std::vector<std::vector<double>> mathematical;  // per component
  FitError error;                                 // of the fitted assembly, by simulation
  long evaluations = 0;                           // of e^2, CMA-ES and polish; <= budget
  int restarts = 0;
  double seconds = 0.0;
  FitStop stop = FitStop::kBudget;
  std::string stop_reason;  // one sentence with the numbers, for the output
};

// Throws InvalidParameter for options out of range (FitOptions::Validate), and
// std::invalid_argument when no shape point gives a finite e^2 (data whose magnitudes overflow
// the sums of squares, for instance).
FitResult Fit(const ModelParametrisation& model, const FitData& data, const FitOptions& options);

// Samples that enter e^2 over all tests (the fitted spans).
long FittedSamples(const FitData& data);

// The components whose every amplitude (stiffness, or c) the fit set to zero: they carry no force
// on the data, and the laws they name need a positive stiffness. Indices, ascending.
std::vector<std::size_t> ZeroComponents(const ModelParametrisation& model,
                                        const Eigen::VectorXd& amplitudes);

// The same fit without the components `drop` (ZeroComponents): the forces, and so e^2, are
// unchanged; the point and amplitudes lose the dropped components' entries. Returns the kept
// components' specifications.
std::vector<ComponentSpec> DropComponents(const ModelParametrisation& model,
                                          const std::vector<std::size_t>& drop, FitResult* fit);

}  // namespace isolab::identification
