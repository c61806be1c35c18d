#include "isolab/cyclic/test_data_checks.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "isolab/core/errors.h"
#include "isolab/core/hardware_threads.h"

namespace isolab::cyclic {

void RequireUnits(const io::CyclicTestSet& set, bool units_given, const std::string& how) {
  if (units_given || set.without_units.empty()) return;
  throw InputError({set.without_units.front()},
                   fmt::format("no '# units: force ..., length ...' line: give the data's units "
                               "in the file or with {} (read as kN and mm, data in kip and in "
                               "would fit with the same e^2 and stiffnesses 5.7 times too large)",
                               how));
}

io::CyclicTestSet ReadCheckedTests(const std::vector<std::string>& files,
                                   const std::string& force_unit, const std::string& length_unit,
                                   const UnitSystem& model_units, const std::string& how) {
  io::CyclicTestSet set = io::ReadCyclicTests(files, {force_unit, length_unit}, model_units);
  RequireUnits(set, !force_unit.empty() && !length_unit.empty(), how);
  RequireFiniteSquares(set);
  return set;
}

void RequireFiniteSquares(const io::CyclicTestSet& set) {
  constexpr double kLargest = 1e150;  // its square, 1e300, still fits a double
  for (std::size_t i = 0; i < set.tests.size(); ++i) {
    const auto& test = set.tests[i];
    for (const auto& [column, values] :
         {std::pair{"force", &test.force}, std::pair{"displacement", &test.displacement}}) {
      for (const double value : *values) {
        if (std::abs(value) > kLargest) {
          throw InputError(
              {i < set.source.size() ? set.source[i] : std::string("data")},
              fmt::format("test '{}': column '{}' reaches {:g}: beyond {:g} in magnitude its "
                          "square overflows, and no fit of it is finite (rescale the data or "
                          "give its units)",
                          test.name, column, value, kLargest));
        }
      }
    }
  }
}

void RequireMoreSamplesThanParameters(const identification::FitData& data,
                                      const identification::ModelParametrisation& model,
                                      const std::string& spec_path) {
  const long samples = identification::FittedSamples(data);
  const long parameters = model.dimension() + model.amplitude_count();
  if (samples <= parameters) {
    throw InputError(
        {spec_path},
        fmt::format("{} parameters to identify ({} shape coordinates and {} stiffnesses) from {} "
                    "samples: the data cannot determine them; give more data or fewer components",
                    parameters, model.dimension(), model.amplitude_count(), samples));
  }
}

std::string FitWork::Describe(double limit) const {
  return fmt::format(
      "work: up to {} evaluations x {} samples x {} law{} = {:.2g} (limit {:.0e}); one "
      "evaluation took {:.3g} ms here: at most about {:.0f} s on {} thread{}",
      evaluations, samples, laws, laws == 1 ? "" : "s", Work(), limit, 1e3 * probe_seconds,
      Seconds(), threads, threads == 1 ? "" : "s");
}

FitWork EstimateFitWork(const identification::ModelParametrisation& model,
                        const identification::FitData& data,
                        const identification::FitOptions& options) {
  FitWork work;
  work.evaluations = options.budget;
  work.samples = identification::FittedSamples(data);
  for (const auto& spec : model.components()) {
    switch (spec.type) {
      case hysteresis::LawType::kLinearSpring:
      case hysteresis::LawType::kDashpot:
      case hysteresis::LawType::kTrilinearElastic:
        break;
      default:
        ++work.laws;
    }
  }
  work.laws = std::max(work.laws, 1L);
  const int hardware = ThreadsOrHardware(options.threads);
  work.threads = std::max(1, std::min(hardware, options.islands));
  // The first evaluation on a thread allocates the basis that the fit's later ones reuse: the
  // second is the one a fit repeats.
  identification::SolveAmplitudes(model, model.StartPoint(), data);
  const auto start = std::chrono::steady_clock::now();
  identification::SolveAmplitudes(model, model.StartPoint(), data);
  work.probe_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return work;
}

void RequireWorkWithin(const FitWork& work, double limit, bool force, const std::string& where) {
  if (force || work.Work() <= limit) return;
  throw InputError({where}, fmt::format("{}: beyond the limit; lower the budget, fit fewer "
                                        "samples (decimate oversampled data) or force it",
                                        work.Describe(limit)));
}

}  // namespace isolab::cyclic
