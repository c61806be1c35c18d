// What recording a run's time histories costs on top of the run: analysis::Solve on an isolated
// shear building of range(0) stories (the five-story Table 9 building of
// models/buildings/five_story_table9.yaml, its stories repeated), under its 30 s record at 0.005 s
// (6,000 steps; 1,500 at 100 stories and more), without free vibration, range(1):
//   0: no results file (the peaks only, what a study's `runs: none` keeps),
//   1: a summary-only HDF5 file (`isolab run --summary-only`, a study's `runs: summary`),
//   2: every history of every step to HDF5, streamed (`isolab run -o`),
//   3: the same held in memory during the run and written after it (a study's `runs: full`:
//      analysis::HeldResultsFile; the run's thread pays the copy, a writer thread the file).
// Files go to /dev/shm where it exists (tmpfs: the cost measured is isolab's and HDF5's, not a
// disk's). Counter "per_step": seconds per step, the set-up (Prepare) excluded.
// Instructions per step: callgrind with --toggle-collect='isolab::analysis::Solve*'
// (docs/benchmarks.md).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/results_file.h"
#include "isolab/analysis/solve.h"
#include "isolab/model/model_file.h"

namespace isolab::analysis {
namespace {

std::filesystem::path Scratch() {
  const std::filesystem::path shm("/dev/shm");
  const std::filesystem::path base =
      std::filesystem::is_directory(shm) ? shm : std::filesystem::temp_directory_path();
  const std::filesystem::path folder =
      base / ("isolab_analysis_benchmark_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  return folder;
}

// The bundled five-story model with `stories` stories, written beside the original so that its
// record's relative path still holds.
model::ModelFile Building(int stories) {
  const std::string source =
      std::string(ISOLAB_SOURCE_DIR) + "/models/buildings/five_story_table9.yaml";
  if (stories == 5) return model::LoadModelFile(source);
  std::ifstream in(source);
  std::stringstream text;
  text << in.rdbuf();
  const std::string changed = std::regex_replace(text.str(), std::regex("count: 5,"),
                                                 "count: " + std::to_string(stories) + ",");
  const std::filesystem::path path = std::string(ISOLAB_SOURCE_DIR) + "/models/buildings/.bench_" +
                                     std::to_string(::getpid()) + ".yaml";
  std::ofstream(path) << changed;
  model::ModelFile model = model::LoadModelFile(path.string());
  std::filesystem::remove(path);
  return model;
}

void BM_SolveOutput(benchmark::State& state) {
  const int stories = static_cast<int>(state.range(0));
  const int mode = static_cast<int>(state.range(1));
  model::ModelFile model = Building(stories);
  model.analysis.free_vibration = model::FreeVibration{false, 0.0};
  if (stories >= 100) model.analysis.duration = 7.5;
  const Problem problem = Prepare(model, {});
  const std::filesystem::path folder = Scratch();
  SolveOptions options;
  options.analysis = model.analysis;
  if (mode == 1 || mode == 2) options.results_path = (folder / "run.h5").string();
  options.output.summary_only = mode == 1;
  for (auto _ : state) {
    if (mode == 3) {
      HeldResultsFile held((folder / "run.h5").string(),
                           {&problem, &options.analysis, nullptr, nullptr, "", options.output});
      integrators::ResponseObserver* observer = &held;
      const Summary summary = Solve(options, problem, std::span(&observer, 1));
      if (!summary.ok()) state.SkipWithError(summary.run.message.c_str());
      held.Write({&problem, &options.analysis, &summary.run, &summary.peaks, "", options.output});
    } else {
      const Summary summary = Solve(options, problem);
      if (!summary.ok()) state.SkipWithError(summary.run.message.c_str());
    }
  }
  std::filesystem::remove_all(folder);
  state.counters["per_step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * problem.grid.steps,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_SolveOutput)->ArgsProduct({{5, 1000}, {0, 1, 2, 3}})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace isolab::analysis

BENCHMARK_MAIN();
