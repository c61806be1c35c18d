// Cost of identification on the synthetic HDRB tests (the Table 9 system at the paper's ten
// amplitudes, three cycles at 0.5 Hz, 200 samples per cycle, the third fitted):
//  * one evaluation of the 33-parameter nine-component THM1 model (21 shape coordinates: the
//    laws driven through all ten tests, then the 12 stiffnesses solved), as evaluations/s, and
//    of the paper's six-component THM2 rival (30 parameters);
//  * the whole 33-parameter fit at the default budget (60,000 evaluations, CMA-ES islands on all
//    cores, then compass search); target: under 5 minutes on the 2-core machine.
// And on a long irregular record, as measured data are: a 40,000-sample seismic-like history
// (200 Hz, 200 s; a decaying, drifting sum of sines through a BHM2 isolator with 1 % force
// noise), the whole history fitted:
//  * one evaluation of a BHM2 model on it, and the whole BHM2 fit at a budget of 6,000
//    evaluations; target: under a minute on the 2-core machine.
// And on a laboratory campaign of the size that made the convergence stop necessary: the
// friction damper of tests/diagnosis/friction_damper_case.h, ten tests at 1024 Hz (150,538
// samples), a BHM2 fitted at the default budget (60,000 evaluations) with the convergence stop
// (argument 1) and without it (0, the whole budget), as isolab fit runs it.
#include <benchmark/benchmark.h>

#include <cmath>

#include "diagnosis/friction_damper_case.h"
#include "identification/table9_assembly.h"
#include "isolab/identification/fit.h"
#include "isolab/identification/synthetic_tests.h"

namespace isolab::identification {
namespace {

using hysteresis::LawType;

FitData HdrbData() {
  const hysteresis::ParallelAssembly table9 = testing::Table9ExactAssembly();
  return SelectCycles(
      SyntheticTests(table9,
                     {{5, 30, 50, 70, 100, 120, 140, 160, 180, 200}, {2.0}, 3, 200, 0.0, 1}),
      {3});
}

std::vector<ComponentSpec> NineThm1() {
  std::vector<ComponentSpec> specs;
  const auto add = [&](LawType type, int count) {
    for (int i = 0; i < count; ++i)
      specs.push_back({"c" + std::to_string(specs.size() + 1), type, {}, {}, {}});
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

// The paper's rival model for the same tests: six THM2 laws (30 parameters, 12 shape coordinates),
// each a run of an elastoplastic law and two columns formed from the displacement.
void BM_EvaluateSixThm2(benchmark::State& state) {
  const FitData data = HdrbData();
  std::vector<ComponentSpec> specs;
  for (int i = 0; i < 6; ++i)
    specs.push_back({"c" + std::to_string(i + 1), LawType::kThm2, {}, {}, {}});
  const ModelParametrisation model(specs, ScalesOf(data));
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
  state.counters["evaluations"] = result.evaluations;
}

// The long record: sums of sines at isolation-like periods (1.5 to 4 s) under an envelope, a
// slow drift, through BHM2 (k0 = 13, k1 = 3.6 kN/mm, uy = 4.6 mm, as fitted to BNCS ICA50).
FitData LongRecord() {
  CyclicTestData test;
  test.name = "long";
  for (int k = 0; k < 40000; ++k) {
    const double t = 0.005 * k;
    const double envelope = std::sin(3.14159265 * t / 200.0);
    test.time.push_back(t);
    test.displacement.push_back(envelope * (60 * std::sin(2.1 * t) + 25 * std::sin(3.7 * t + 1) +
                                            10 * std::sin(1.6 * t + 2)) +
                                2 * std::sin(0.05 * t));
  }
  test.force = SimulateForce(hysteresis::SingleLaw(LawType::kBhm2, {13.0, 3.6, 4.6}), test);
  std::vector<CyclicTestData> tests{test};
  AddForceNoise(&tests, 0.01, 1);
  Segment(&tests[0]);
  return SelectCycles(tests, {});
}

void BM_EvaluateBhm2LongRecord(benchmark::State& state) {
  const FitData data = LongRecord();
  const ModelParametrisation model({{"isolator", LawType::kBhm2, {}, {}, {}}}, ScalesOf(data));
  const std::vector<double> x = model.StartPoint();
  for (auto _ : state) benchmark::DoNotOptimize(SolveAmplitudes(model, x, data).error);
  state.counters["samples"] = static_cast<double>(data.tests[0].time.size());
}

void BM_FitBhm2LongRecord(benchmark::State& state) {
  const FitData data = LongRecord();
  const ModelParametrisation model({{"isolator", LawType::kBhm2, {}, {}, {}}}, ScalesOf(data));
  FitOptions options;
  options.budget = 6000;
  FitResult result;
  for (auto _ : state) result = Fit(model, data, options);
  state.counters["samples"] = static_cast<double>(data.tests[0].time.size());
  state.counters["e2_percent"] = 100 * result.error.total;
  state.counters["k1"] = result.mathematical[0][1];
  state.counters["uy"] = result.mathematical[0][2];
}

void BM_FitBhm2Campaign(benchmark::State& state) {
  const FitData data = SelectCycles(diagnosis::testing::FrictionDamperTests(1024.0), {});
  const ModelParametrisation model({{"isolator", LawType::kBhm2, {}, {}, {}}}, ScalesOf(data));
  FitOptions options;
  if (state.range(0) == 0) options.stop_window = 0;
  FitResult result;
  for (auto _ : state) result = Fit(model, data, options);
  state.counters["samples"] = static_cast<double>(FittedSamples(data));
  state.counters["evaluations"] = result.evaluations;
  state.counters["e2_percent"] = 100 * result.error.total;
  state.counters["e2_mean_percent"] = 100 * result.error.Mean();
}

BENCHMARK(BM_EvaluateNineThm1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EvaluateSixThm2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EvaluateBhm2LongRecord)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FitBhm2LongRecord)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_FitNineThm1)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_FitBhm2Campaign)
    ->Arg(1)
    ->Arg(0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

}  // namespace
}  // namespace isolab::identification

BENCHMARK_MAIN();
