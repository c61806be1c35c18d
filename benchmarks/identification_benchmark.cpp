// Cost of identification on the synthetic HDRB tests (the Table 9 system at the paper's ten
// amplitudes, three cycles at 0.5 Hz, 200 samples per cycle, the third fitted):
//  * one evaluation of the 33-parameter nine-component THM1 model (21 shape coordinates: the
//    laws driven through all ten tests, then the 12 stiffnesses solved), as evaluations/s;
//  * the whole 33-parameter fit at the default budget (60,000 evaluations, CMA-ES islands on all
//    cores, then compass search); target: under 5 minutes on the 2-core machine.
#include <benchmark/benchmark.h>

#include <thread>

#include "isolab/identification/fit.h"
#include "identification/table9_assembly.h"
#include "isolab/identification/synthetic_tests.h"

namespace isolab::identification {
namespace {

using hysteresis::LawType;

FitData HdrbData() {
  const hysteresis::ParallelAssembly table9 = testing::Table9ExactAssembly();
  return SelectCycles(
      SyntheticTests(table9, {{5, 30, 50, 70, 100, 120, 140, 160, 180, 200}, {2.0}, 3, 200, 0.0, 1}),
      {3});
}

std::vector<ComponentSpec> NineThm1() {
  std::vector<ComponentSpec> specs;
  const auto add = [&](LawType type, int count) {
    for (int i = 0; i < count; ++i) specs.push_back({"c" + std::to_string(specs.size() + 1), type, {}, {}, {}});
  };
  add(LawType::kTrilinearElastic, 3);
  add(LawType::kThm1, 4);
  add(LawType::kElastoplastic, 2);
  return specs;
}

void BM_EvaluateNineThm1(benchmark::State& state) {
  const FitData data = HdrbData();
  const ModelParametrisation model(NineThm1(), ScalesOf(data));
  const std::vector<double> x = model.StartPoint();
  for (auto _ : state) benchmark::DoNotOptimize(SolveAmplitudes(model, x, data).error);
  state.counters["evaluations_per_s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void BM_FitNineThm1(benchmark::State& state) {
  const FitData data = HdrbData();
  const ModelParametrisation model(NineThm1(), ScalesOf(data));
  FitResult result;
  for (auto _ : state) result = Fit(model, data, {});
  state.counters["e2_percent"] = 100 * result.error.total;
  state.counters["evaluations_per_s"] = result.evaluations / result.seconds;
  state.counters["threads"] = std::max(2u, std::thread::hardware_concurrency());
}

BENCHMARK(BM_EvaluateNineThm1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FitNineThm1)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace isolab::identification

BENCHMARK_MAIN();
