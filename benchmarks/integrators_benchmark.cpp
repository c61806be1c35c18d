// Cost per Newmark-Newton step (full Newton, KLU), all output recorded:
//  * an SDOF on one THM1 isolator, 10,000 steps (target <= 0.2 us per step);
//  * the five-story building on the nine-component Table 9 isolator (target <= 1 us per step),
//    and the same arithmetic written by hand for that one model (newmark_floor.h), the floor
//    the general code is measured against; the same pair for the five-story building of the
//    side-by-side comparison with OpenSees (a BHM2 isolator, stories of a spring and a dashpot);
//  * an isolated shear building of 5 to 1000 stories (Rayleigh damping keeps the tangent sparse),
//    on the Table 9 isolator and on a linear isolator that never yields, for the growth of the
//    cost with size;
//  * the set-up of such a building (masses, connections, Rayleigh damping from two modes);
//  * the same five-story building on IDA at rtol 1e-4, 1e-6 and 1e-8 (60 s of record, output at
//    0.01 s), with its internal steps and events per second of record.
//  * buildings in plan: the five-story Table 9 building in plan on four coupled (and
//    uncoupled) Table 9 bearings under two components, against the one-direction five-story
//    model above (target within 5x), and a plan building of 5 to 1000 stories on four linear
//    isolators (target: linear in stories); and both models on one lead-rubber bearing or
//    friction pendulum a bearing.
//  * one factorisation and solve of an effective tangent by each linear solver
//    (tangent_solver.h) on the pattern of a shear building with relative Rayleigh damping and on
//    bands of a few diagonals: the measurements behind the automatic choice's thresholds.
// Counters: "per_step" is seconds per step, "solves_per_step" linear solves (Newton
// iterations) per step. The excitation is isolab's seeded filtered noise.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "isolab/analysis/synthetic_motion.h"
#include "isolab/hysteresis/law_parameters.h"
#include "isolab/hysteresis/parallel_slider.h"
#include "isolab/integrators/ida.h"
#include "isolab/integrators/newmark.h"
#include "isolab/model/model_file.h"
#include "isolab/structure/plan_building.h"
#include "isolab/structure/shear_building.h"
#include "newmark_floor.h"
#include "tangent_solver.h"

namespace isolab::integrators {
namespace {

using hysteresis::LawType;
using hysteresis::ParallelAssembly;

// 100 s of filtered noise at 0.01 s, PGA 0.35 g, in mm/s^2 (or, with g = 9.80665, in m/s^2).
Excitation Noise(double g = 9806.65) {
  analysis::FilteredNoiseSpec spec;
  spec.duration = 100.0;
  spec.pga = 0.35;
  const io::Record record = analysis::FilteredNoiseRecord(spec);
  Excitation excitation = Excitation::Uniform({});
  excitation.ground[0].acceleration.dt = record.dt;
  for (const double a : record.values) excitation.ground[0].acceleration.values.push_back(a * g);
  return excitation;
}

ParallelAssembly Single(LawType type, std::vector<double> math) {
  return hysteresis::SingleLaw(type, std::move(math));
}

void CountSteps(benchmark::State& state, int steps, long solves) {
  state.counters["per_step"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * steps,
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["solves_per_step"] = static_cast<double>(solves) / (state.iterations() * steps);
}

void RunSteps(benchmark::State& state, const structure::Structure& structure, int steps,
              const Excitation& excitation = Noise(), const NewmarkOptions& options = {}) {
  ResponseHistory response;
  long solves = 0;
  for (auto _ : state) {
    const RunSummary summary = RunNewmark(structure, excitation, {0.01, steps}, options, &response);
    if (!summary.ok()) state.SkipWithError(summary.message.c_str());
    solves += summary.newton_iterations;
  }
  CountSteps(state, steps, solves);
}

void BM_SdofThm1(benchmark::State& state) {
  // 31.7 t on the Table 7 THM1 (hardening) law, in kN, mm, s.
  const auto sdof =
      structure::BuildSdof(0.0317, 0.0, Single(LawType::kThm1, {1.0, 0.2, 0.45, 20, 120}))
          .structure;
  RunSteps(state, sdof, 10000);
}

structure::Structure IsolatedBuilding(int stories, const ParallelAssembly& isolation) {
  structure::ShearBuilding building;
  for (int i = 0; i < stories; ++i) {
    building.stories.push_back({"story", 0.025, 3200.0, Single(LawType::kLinearSpring, {76.0})});
  }
  building.isolated = true;
  building.base_mass = 0.025;
  building.isolation = isolation;
  building.damping.kind = structure::SuperstructureDamping::Kind::kRayleigh;
  building.damping.rayleigh_ratios[0] = building.damping.rayleigh_ratios[1] = 0.02;
  return structure::BuildShearBuilding(building).structure;
}

ParallelAssembly Table9() {
  return model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) +
                              "/models/paper/table9_thm1_system.yaml")
      .isolation;
}

// A linear spring and a dashpot: 2.5 s and 10 % damping on the whole building's mass.
ParallelAssembly LinearIsolator(int stories) {
  const double mass = 0.025 * (stories + 1), w = 2.0 * std::numbers::pi / 2.5;
  using hysteresis::LawParameters, hysteresis::ParameterForm;
  const auto law = [](LawType type, double value) {
    return LawParameters::Make(type, ParameterForm::kMathematical, std::vector<double>{value});
  };
  return ParallelAssembly({{"spring", law(LawType::kLinearSpring, w * w * mass)},
                           {"dashpot", law(LawType::kDashpot, 2.0 * 0.1 * w * mass)}});
}

void BM_FiveStoryTable9(benchmark::State& state) {
  RunSteps(state, IsolatedBuilding(5, Table9()), 6000);
}

// Times a hand-written floor (newmark_floor.h) over `steps` steps of `excitation`, once its
// response has been checked against RunNewmark's on `building`: the same numbers of solves and
// factorisations, and displacements within 1e-9 of the peak.
template <class Floor>
void TimeFloor(benchmark::State& state, Floor& floor, const structure::Structure& building,
               const Excitation& excitation, int steps) {
  typename Floor::Output output;
  long solves = floor.Run(excitation.ground[0].acceleration, 0.01, steps, &output);
  ResponseHistory response;
  const RunSummary summary = RunNewmark(building, excitation, {0.01, steps}, {}, &response);
  const double peak = response.displacement.cwiseAbs().maxCoeff();
  for (int row = 0; row <= steps; ++row) {
    for (int i = 0; i < Floor::kDofs; ++i) {
      if (std::abs(output.displacement[row * Floor::kDofs + i] - response.displacement(row, i)) >
          1e-9 * peak) {
        state.SkipWithError("the floor's response differs from RunNewmark's");
        return;
      }
    }
  }
  if (solves != summary.newton_iterations) {
    state.SkipWithError("the floor makes a different number of solves than RunNewmark");
    return;
  }
  if (floor.factorisations() != summary.factorisations) {
    state.SkipWithError("the floor factorises a different number of times than RunNewmark");
    return;
  }
  solves = 0;
  for (auto _ : state) solves += floor.Run(excitation.ground[0].acceleration, 0.01, steps, &output);
  CountSteps(state, steps, solves);
}

// The hand-written floor on the same model, record and step, factorising with `Solver`
// (newmark_floor.h); its response must be RunNewmark's.
template <template <int> class Solver>
void FiveStoryTable9Floor(benchmark::State& state) {
  constexpr int kSteps = 6000;
  const structure::Structure building = IsolatedBuilding(5, Table9());
  const auto& connections = building.members();
  std::array<hysteresis::SeriesSlider, 9> isolator;
  for (int c = 0; c < 9; ++c) {
    isolator[c] = std::get<hysteresis::SeriesSlider>(connections[0].assembly.kernels()[c]);
  }
  std::array<hysteresis::ElasticSpring, 5> stories;
  for (int s = 0; s < 5; ++s) {
    stories[s] = std::get<hysteresis::ElasticSpring>(connections[s + 1].assembly.kernels()[0]);
  }
  using Floor = benchmarks::NewmarkFloor<5, 9, Solver>;
  typename Floor::Vector mass;
  typename Floor::Matrix damping;
  const Eigen::MatrixXd c = Eigen::MatrixXd(building.viscous_damping());
  for (int i = 0; i < Floor::kDofs; ++i) {
    mass[i] = building.mass()[i];
    for (int j = 0; j < Floor::kDofs; ++j) damping[i][j] = c(i, j);
  }
  Floor floor(mass, damping, isolator, stories);
  TimeFloor(state, floor, building, Noise(), kSteps);
}

// The floor as written by hand: a dense LDL^T of the 6 x 6 tangent.
void BM_FiveStoryTable9Floor(benchmark::State& state) {
  FiveStoryTable9Floor<benchmarks::DenseLdlt>(state);
}

// The floor with RunNewmark's KLU: what is left between the two is the cost of generality.
void BM_FiveStoryTable9FloorKlu(benchmark::State& state) {
  FiveStoryTable9Floor<benchmarks::KluDense>(state);
}

// The five-story building of the side-by-side comparison with OpenSees
// (benchmarks/opensees_side_by_side.sh; the peers' shear_building.tcl): 100 t a level, stories of
// a linear spring and a dashpot (stiffness-proportional damping on the story drifts), one BHM2
// isolator; kN, m, s. Run for 10,000 steps of Noise() in m/s^2.
constexpr double kTwinStoryStiffness = 100000.0, kTwinStoryDashpot = 1111.0147397616761;
constexpr int kTwinSteps = 10000;

Excitation TwinNoise() { return Noise(9.80665); }

structure::Structure OpenSeesTwin() {
  structure::ShearBuilding building;
  using hysteresis::LawParameters, hysteresis::ParameterForm;
  const auto law = [](LawType type, std::vector<double> values) {
    return LawParameters::Make(type, ParameterForm::kMathematical, std::move(values));
  };
  for (int i = 0; i < 5; ++i) {
    building.stories.push_back(
        {"story", 100.0, 3.0,
         ParallelAssembly({{"k", law(LawType::kLinearSpring, {kTwinStoryStiffness})},
                           {"c", law(LawType::kDashpot, {kTwinStoryDashpot})}})});
  }
  building.isolated = true;
  building.base_mass = 100.0;
  building.isolation =
      Single(LawType::kBhm2, {37899.280900183134, 3789.9280900183135, 0.0077653188400885441});
  return structure::BuildShearBuilding(building).structure;
}

// The hand-written floor of the OpenSees twin's step: its story dashpots as the dense damping
// matrix (the same forces on the dofs, but its recorded story and law forces leave the dashpots
// out), full Newton and a dense LDL^T. Its response must be RunNewmark's. The floor records its
// rows in memory and tracks no peaks: what isolab's `run` adds beyond it with every history is
// the peaks, the file and its rows.
void BM_FiveStoryTwinFloor(benchmark::State& state) {
  const structure::Structure building = OpenSeesTwin();
  const auto& members = building.members();
  using Isolator = hysteresis::ParallelSlider;  // BHM2's kernel
  std::array<Isolator, 1> isolator{std::get<Isolator>(members[0].assembly.kernels()[0])};
  std::array<hysteresis::ElasticSpring, 5> stories;
  using Floor = benchmarks::NewmarkFloor<5, 1, benchmarks::DenseLdlt, Isolator>;
  typename Floor::Vector mass;
  typename Floor::Matrix damping{};
  for (int s = 0; s < 5; ++s) {
    stories[s] = std::get<hysteresis::ElasticSpring>(members[s + 1].assembly.kernels()[0]);
    damping[s][s] += kTwinStoryDashpot;
    damping[s + 1][s + 1] += kTwinStoryDashpot;
    damping[s][s + 1] -= kTwinStoryDashpot;
    damping[s + 1][s] -= kTwinStoryDashpot;
  }
  for (int i = 0; i < Floor::kDofs; ++i) mass[i] = building.mass()[i];
  Floor floor(mass, damping, isolator, stories);
  TimeFloor(state, floor, building, TwinNoise(), kTwinSteps);
}

// RunNewmark on the twin, every output recorded in memory (ResponseHistory), as the floor records.
void BM_FiveStoryTwin(benchmark::State& state) {
  RunSteps(state, OpenSeesTwin(), kTwinSteps, TwinNoise());
}

void BM_StoriesTable9(benchmark::State& state) {
  const int stories = static_cast<int>(state.range(0));
  // A cost benchmark, not a design: the same bearing under every height.
  RunSteps(state, IsolatedBuilding(stories, Table9()), 2000);
}

// BM_StoriesTable9 (range(0) stories) with the linear solver range(1) forced
// (NewmarkOptions::LinearSolver: 1 KLU, 2 dense, 3 banded): where the automatic choice changes.
void BM_StoriesTable9Solver(benchmark::State& state) {
  NewmarkOptions options;
  options.linear_solver = static_cast<NewmarkOptions::LinearSolver>(state.range(1));
  RunSteps(state, IsolatedBuilding(static_cast<int>(state.range(0)), Table9()), 2000, Noise(),
           options);
}

// Without yielding, every step's equations are linear: one solve per step is the ideal.
void BM_StoriesLinearIsolator(benchmark::State& state) {
  const int stories = static_cast<int>(state.range(0));
  RunSteps(state, IsolatedBuilding(stories, LinearIsolator(stories)), 10000);
}

// Building the structure: masses, connections, the sparse pattern and Rayleigh damping.
void BM_SetUpRayleighBuilding(benchmark::State& state) {
  const int stories = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const structure::Structure building = IsolatedBuilding(stories, LinearIsolator(stories));
    benchmark::DoNotOptimize(building.viscous_damping().nonZeros());
  }
}

void BM_FiveStoryTable9Ida(benchmark::State& state) {
  const structure::Structure building = IsolatedBuilding(5, Table9());
  const Excitation excitation = Noise();
  IdaOptions options;
  options.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  options.absolute_tolerance = options.relative_tolerance * 1e-3;
  ResponseHistory response;
  RunSummary summary;
  for (auto _ : state) {
    summary = RunIda(building, excitation, {0.01, 6000}, options, &response);
    if (!summary.ok()) state.SkipWithError(summary.message.c_str());
  }
  state.counters["ida_steps_per_s"] = static_cast<double>(summary.ida_steps) / 60.0;
  state.counters["events_per_s"] = static_cast<double>(summary.events) / 60.0;
}

// H1: Noise() along x; H2: the same generator with another seed along y, on a plan structure laid
// out as `layout`.
Excitation PlanNoise(const structure::Layout& layout) {
  analysis::FilteredNoiseSpec spec;
  spec.duration = 100.0;
  spec.pga = 0.30;
  spec.seed = 2;
  const io::Record record = analysis::FilteredNoiseRecord(spec);
  integrators::SampledHistory y{record.dt, {}};
  for (const double a : record.values) y.values.push_back(a * 9806.65);
  return Excitation::Horizontal(layout, Noise().ground[0].acceleration, std::move(y));
}

structure::PlanBuilding BundledPlanBuilding() {
  return model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) +
                              "/models/plan/five_story_table9_plan.yaml")
      .structure->plan;
}

// A plan building under PlanNoise().
void RunPlanSteps(benchmark::State& state, const structure::LaidOutStructure& building, int steps) {
  RunSteps(state, building.structure, steps, PlanNoise(building.layout));
}

// The bundled plan model (models/plan/five_story_table9_plan.yaml): 18 dofs, 4 bearings of 9
// components each; range(0) = 1 makes every bearing an uncoupled pair.
void BM_PlanFiveStoryTable9(benchmark::State& state) {
  structure::PlanBuilding building = BundledPlanBuilding();
  if (state.range(0) == 1) {
    for (structure::PlanIsolatorSite& site : building.isolators) {
      std::vector<hysteresis::PlanComponent> pairs = site.assembly.components();
      for (hysteresis::PlanComponent& c : pairs) c.law_y = c.law;
      site.assembly = hysteresis::PlanAssembly(std::move(pairs));
    }
  }
  RunPlanSteps(state, structure::BuildPlanBuilding(building), 6000);
}

// The bundled plan model with the linear solver range(0) forced (as BM_StoriesTable9Solver).
void BM_PlanFiveStoryTable9Solver(benchmark::State& state) {
  const structure::LaidOutStructure building = structure::BuildPlanBuilding(BundledPlanBuilding());
  NewmarkOptions options;
  options.linear_solver = static_cast<NewmarkOptions::LinearSolver>(state.range(0));
  RunSteps(state, building.structure, 2000, PlanNoise(building.layout), options);
}

// The devices engineers specify, one law a bearing, for 150 t (the one-direction building's mass
// and each plan bearing's share): range(0) = 0 a lead-rubber bearing without heating (Qd 6 % of
// the weight, T = 4.2 s on Kd), 1 a friction pendulum with velocity-dependent friction on the
// same period (docs/bearings.md's example).
hysteresis::LawParameters Device(int device) {
  using hysteresis::LawParameters, hysteresis::ParameterForm;
  if (device == 0) {
    return LawParameters::Make(
        LawType::kLeadRubber, ParameterForm::kMechanical,
        std::vector<double>{88.26, 0.3391, 3.391, NAN, NAN, NAN, NAN, NAN, NAN, NAN});
  }
  return LawParameters::Make(LawType::kFrictionPendulum, ParameterForm::kMechanical,
                             std::vector<double>{1471.0, 4338.0, 0.5, NAN, 0.03, 0.06, 0.02});
}

void BM_FiveStoryDevice(benchmark::State& state) {
  const ParallelAssembly isolation({{"bearing", Device(static_cast<int>(state.range(0)))}});
  RunSteps(state, IsolatedBuilding(5, isolation), 6000);
}

// The bundled plan model with each of its four bearings one coupled device of Device().
void BM_PlanFiveStoryDevice(benchmark::State& state) {
  structure::PlanBuilding building = BundledPlanBuilding();
  const hysteresis::PlanAssembly bearing(
      {{"bearing", Device(static_cast<int>(state.range(0))), std::nullopt}});
  for (structure::PlanIsolatorSite& site : building.isolators) site.assembly = bearing;
  RunPlanSteps(state, structure::BuildPlanBuilding(building), 6000);
}

// `stories` floors of 100 t on a 24 m x 16 m plan, 5 % eccentric, stories of 304 kN/mm, four
// corner isolators that never yield (spring and dashpot: 2.5 s, 10 % on the whole mass).
void BM_PlanStoriesLinearIsolators(benchmark::State& state) {
  const int stories = static_cast<int>(state.range(0));
  const double mass = 0.1, w = 2.0 * std::numbers::pi / 2.5;
  const double inertia = mass * (24000.0 * 24000.0 + 16000.0 * 16000.0) / 12.0;
  const double share = 0.25 * mass * (stories + 1);
  using hysteresis::LawParameters, hysteresis::ParameterForm;
  const auto law = [](LawType type, double value) {
    return LawParameters::Make(type, ParameterForm::kMathematical, std::vector<double>{value});
  };
  const hysteresis::PlanAssembly isolator(
      {{"spring", law(LawType::kLinearSpring, w * w * share), std::nullopt},
       {"dashpot", law(LawType::kDashpot, 2.0 * 0.1 * w * share), std::nullopt}});
  structure::PlanBuilding building;
  building.base = {mass, inertia, {13200.0, 8000.0}};
  for (int s = 0; s < stories; ++s) {
    building.stories.push_back({"story",
                                {mass, inertia, {13200.0, 8000.0}},
                                3200.0,
                                {12000.0, 8000.0},
                                Single(LawType::kLinearSpring, {304.0}),
                                Single(LawType::kLinearSpring, {304.0}),
                                Single(LawType::kLinearSpring, {6.3232e10})});
  }
  for (const auto& [x, y] :
       {std::pair{0.0, 0.0}, {24000.0, 0.0}, {0.0, 16000.0}, {24000.0, 16000.0}}) {
    building.isolators.push_back({"corner", {x, y}, isolator});
  }
  building.damping = {true, {0.4, 0.1}, {0.02, 0.02}};
  RunPlanSteps(state, structure::BuildPlanBuilding(building), 10000);
}

// One Newton iteration's linear algebra: factorise a tangent and solve once, with the solver
// range(0) (NewmarkOptions::LinearSolver: 1 KLU, 2 dense, 3 banded), n = range(1) dofs, on the
// pattern of an isolated shear building with relative Rayleigh damping (range(2) = 0: tridiagonal
// with a full base row and column) or on a band of range(2) diagonals each side. The values are
// those of a diagonally dominant matrix, slightly unsymmetric, changed a little every iteration.
void BM_TangentSolver(benchmark::State& state) {
  const auto kind = static_cast<NewmarkOptions::LinearSolver>(state.range(0));
  const int n = static_cast<int>(state.range(1)), width = static_cast<int>(state.range(2));
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const bool in =
          width == 0 ? std::abs(i - j) <= 1 || i == 0 || j == 0 : std::abs(i - j) <= width;
      if (in) entries.emplace_back(i, j, i == j ? 4.0 * (width + 1) : -1.0 - 0.01 * (i > j));
    }
  }
  structure::SparseMatrix matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  matrix.makeCompressed();
  if (width == 0) matrix.coeffRef(0, 0) = 2.0 * n;
  TangentSolver solver(matrix, kind);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(n);
  Eigen::VectorXd x(n);
  double* diagonal = &matrix.coeffRef(n - 1, n - 1);
  for (auto _ : state) {
    *diagonal += 1e-9;
    if (!solver.Factorize(matrix)) state.SkipWithError("singular");
    x = b;
    solver.Solve(&x);
    benchmark::DoNotOptimize(x.data());
  }
}

BENCHMARK(BM_SdofThm1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanFiveStoryTable9)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanStoriesLinearIsolators)
    ->Arg(5)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanFiveStoryDevice)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FiveStoryTable9)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FiveStoryDevice)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FiveStoryTable9Floor)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FiveStoryTable9FloorKlu)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FiveStoryTwin)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FiveStoryTwinFloor)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FiveStoryTable9Ida)->Arg(4)->Arg(6)->Arg(8)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StoriesTable9)
    ->Arg(5)
    ->Arg(10)
    ->Arg(50)
    ->Arg(100)
    ->Arg(500)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StoriesLinearIsolator)->Arg(5)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SetUpRayleighBuilding)->Arg(5)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StoriesTable9Solver)
    ->ArgsProduct({{2, 5, 8, 11, 14, 17, 23, 35}, {1, 2, 3}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanFiveStoryTable9Solver)->DenseRange(1, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TangentSolver)
    ->ArgsProduct({{1, 2, 3}, {2, 6, 9, 12, 18, 24, 36, 60}, {0}})
    ->ArgsProduct({{1, 3}, {1001}, {0, 1, 2, 3, 4, 6, 8}});

}  // namespace
}  // namespace isolab::integrators

BENCHMARK_MAIN();
