// Cost of response spectra on the bundled 30 s synthetic record (ground_motions/
// fwn_firm_seed1.at2, 3001 samples at 0.01 s):
//  * the elastic spectrum over 100 periods (0.05 to 5 s) at 5 % damping, exact recurrence;
//  * one constant-ductility curve (mu = 4, 5 %, elastoplastic) over 20 periods (0.1 to 2 s):
//    Newmark runs of the scan and the bisection;
//  * one Newmark run of the inelastic SDOF at T = 0.5 s (h = 0.01 s, 3000 steps);
//  * the pair's spectra (RotD50, RotD100, components, geometric mean) over the same 100 periods,
//    with ground_motions/h2_fwn_firm_seed3.at2 as H2: against the elastic spectrum, the cost
//    factor SpectrumSteps counts a pair at (spectrum_work.h).
// Counters: "per_period" seconds per period, "runs" Newmark runs per curve.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "isolab/io/record.h"
#include "isolab/spectra/constant_ductility.h"
#include "isolab/spectra/elastic_spectrum.h"
#include "isolab/spectra/rotd_spectrum.h"

namespace isolab::spectra {
namespace {

integrators::SampledHistory Record(const char* name = "fwn_firm_seed1.at2") {
  const io::Record record =
      io::ReadRecord(std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/" + name);
  integrators::SampledHistory ground{record.dt, {}};
  for (const double a : record.values) ground.values.push_back(a * 9.80665);
  return ground;
}

std::vector<double> Periods(double start, double step, int count) {
  std::vector<double> periods;
  for (int k = 0; k < count; ++k) periods.push_back(start + k * step);
  return periods;
}

void BM_ElasticSpectrum100Periods(benchmark::State& state) {
  const auto ground = Record();
  const auto periods = Periods(0.05, 0.05, 100);
  const std::vector<double> damping{0.05};
  for (auto _ : state) {
    benchmark::DoNotOptimize(ComputeElasticSpectrum(ground, periods, damping));
  }
  state.counters["per_period"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * periods.size(),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_ElasticSpectrum100Periods)->Unit(benchmark::kMillisecond);

void BM_PairSpectrum100Periods(benchmark::State& state) {
  const auto h1 = Record(), h2 = Record("h2_fwn_firm_seed3.at2");
  const auto periods = Periods(0.05, 0.05, 100);
  const std::vector<double> damping{0.05};
  for (auto _ : state) {
    benchmark::DoNotOptimize(ComputePairSpectrum(h1, h2, periods, damping));
  }
  state.counters["per_period"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * periods.size(),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PairSpectrum100Periods)->Unit(benchmark::kMillisecond);

void BM_ConstantDuctilityCurve20Periods(benchmark::State& state) {
  const auto ground = Record();
  const auto periods = Periods(0.1, 0.1, 20);
  const std::vector<double> damping{0.05}, ductility{4.0};
  long runs = 0;
  for (auto _ : state) {
    const auto spectrum = ComputeConstantDuctilitySpectrum(ground, periods, damping, ductility, {});
    runs = spectrum.newmark_runs;
  }
  state.counters["per_period"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * periods.size(),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["runs"] = static_cast<double>(runs);
}
BENCHMARK(BM_ConstantDuctilityCurve20Periods)->Unit(benchmark::kMillisecond);

void BM_InelasticSdofRun(benchmark::State& state) {
  integrators::Excitation excitation = integrators::Excitation::Uniform({});
  excitation.ground[0].acceleration = Record();
  DuctilityDemand demand(excitation, 0.5, 0.05, {});
  for (auto _ : state) benchmark::DoNotOptimize(demand(0.25));
}
BENCHMARK(BM_InelasticSdofRun)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace isolab::spectra

BENCHMARK_MAIN();
