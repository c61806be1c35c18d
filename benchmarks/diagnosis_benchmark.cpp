// Cost of a diagnosis on the hidden-effect cases (models/diagnosis/, the protocol of
// scripts/generate_diagnosis_cases.sh: 12 tests, 7212 samples, 1 % noise) from a one-BHM2 base:
// the base fit, the detectors on its residual, and each refit of a supported candidate. Target:
// under two minutes per case on the 2-core machine. Counters: the effects named, e^2 of the base
// and the final model, and the final e^2 over the noise floor.
#include <benchmark/benchmark.h>

#include "diagnosis/hidden_effect_cases.h"
#include "isolab/diagnosis/diagnose.h"

namespace isolab::diagnosis {
namespace {

const char* const kCases[] = {"null.yaml",
                              "rate_dependence.yaml",
                              "amplitude_dependent_dissipation.yaml",
                              "large_amplitude_hardening.yaml",
                              "cyclic_degradation.yaml",
                              "two_effects.yaml",
                              "asymmetric_strength.yaml",
                              "backlash.yaml"};

void BM_Diagnose(benchmark::State& state) {
  const auto index = static_cast<std::size_t>(state.range(0));
  const identification::FitData data = HiddenEffectData({kCases[index], 11u + unsigned(index)});
  Diagnosis result;
  for (auto _ : state) {
    result = Diagnose({{"base", hysteresis::LawType::kBhm2, {}, {}, {}}}, data, {});
  }
  state.SetLabel(kCases[index]);
  state.counters["effects"] = static_cast<double>(result.steps.size());
  state.counters["base_e2_percent"] = 100 * result.base.fit.error.total;
  state.counters["final_e2_percent"] = 100 * result.final_model.fit.error.total;
  state.counters["final_over_floor"] = result.final_model.fit.error.total / result.noise_floor;
}

void BM_Detectors(benchmark::State& state) {
  const identification::FitData data = HiddenEffectData({"two_effects.yaml", 16});
  const hysteresis::ParallelAssembly base =
      hysteresis::SingleLaw(hysteresis::LawType::kBhm2, {1.5, 0.3, 8});
  for (auto _ : state) {
    const Discrepancy discrepancy = Discrepancy::Of(base, data);
    for (const Effect effect : AllEffects()) benchmark::DoNotOptimize(Detect(effect, discrepancy));
  }
}

BENCHMARK(BM_Diagnose)->DenseRange(0, 7)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_Detectors)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace isolab::diagnosis

BENCHMARK_MAIN();
