// Checks `isolab fit`, `isolab diagnose` and their Python twins make on measured tests before
// identifying anything, each an InputError saying where and what was allowed:
//  * units: a file without a "# units:" line is refused unless the caller gave both units. Read
//    silently as kN and mm, data in kip and in give a stiffness 5.7 times too large with the same
//    e^2, and nothing else would flag it;
//  * magnitudes: a force or displacement whose square overflows (beyond 1e150) makes every sum
//    of squares infinite, so no fit is finite;
//  * samples against parameters: fewer samples than shape coordinates plus stiffnesses cannot
//    determine them;
//  * work: evaluations x samples x laws run per evaluation, said before the fit starts and
//    refused beyond a limit unless forced (a fit of ten million rows ran for minutes with no word
//    of how long it would take).
#pragma once

#include <string>
#include <vector>

#include "isolab/identification/fit.h"
#include "isolab/identification/parametrisation.h"
#include "isolab/io/cyclic_test_file.h"

namespace isolab::cyclic {

// `units_given`: the caller named both the force and the length unit (--force-unit and
// --length-unit). `how`: what to tell the user to give, e.g. "--force-unit and --length-unit".
void RequireUnits(const io::CyclicTestSet& set, bool units_given, const std::string& how);

// Throws InputError naming the file, test and column of the first value beyond 1e150.
void RequireFiniteSquares(const io::CyclicTestSet& set);

// The cyclic tests in `files`, read in `model_units` (or the units the caller gave: both or none,
// `how` naming them) and checked by RequireUnits and RequireFiniteSquares: what the cyclic fit,
// the diagnosis and a force-driven building fit read.
io::CyclicTestSet ReadCheckedTests(const std::vector<std::string>& files,
                                   const std::string& force_unit, const std::string& length_unit,
                                   const UnitSystem& model_units, const std::string& how);

// Throws InputError at `spec_path` when the samples to fit are fewer than the model's parameters
// (shape coordinates plus stiffnesses).
void RequireMoreSamplesThanParameters(const identification::FitData& data,
                                      const identification::ModelParametrisation& model,
                                      const std::string& spec_path);

struct FitWork {
  long evaluations = 0;        // the budget: at most this many
  long samples = 0;            // fitted samples
  long laws = 0;               // laws run through the data at every evaluation (at least 1)
  double probe_seconds = 0.0;  // one evaluation, timed here
  int threads = 1;             // running side by side (FitOptions: min(threads, islands))

  double Work() const { return double(evaluations) * double(samples) * double(laws); }
  // At most this long: every evaluation as long as the probe, shared among the threads.
  double Seconds() const { return probe_seconds * double(evaluations) / double(threads); }
  // "work: up to 60000 evaluations x 7212 samples x 1 law = 4.3e8 (limit 1e11); one evaluation
  // took 0.45 ms here: at most about 14 s on 2 threads".
  std::string Describe(double limit) const;
};

// Above this much work a fit is refused unless forced: about 20 minutes of the 2-core reference
// machine at its 13 ns per sample and law.
inline constexpr double kWorkLimit = 1e11;

// Times one evaluation at the model's start point and estimates the fit's work.
FitWork EstimateFitWork(const identification::ModelParametrisation& model,
                        const identification::FitData& data,
                        const identification::FitOptions& options);

// Throws InputError at `where` when the work exceeds `limit` and `force` is false.
void RequireWorkWithin(const FitWork& work, double limit, bool force, const std::string& where);

}  // namespace isolab::cyclic
