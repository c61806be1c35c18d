// Newmark-Newton against Chopra's Chapter 5 examples (chopra_chapter5.h), a closed-form
// harmonic response (convergence order), and the energy balance.
#include "isolab/integrators/newmark.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "integrators/chopra_chapter5.h"
#include "isolab/core/errors.h"
#include "isolab/hysteresis/law_parameters.h"
#include "isolab/structure/shear_building.h"

namespace isolab::integrators {
namespace {

using hysteresis::LawType;
using hysteresis::ParallelAssembly;

ParallelAssembly Single(LawType type, std::vector<double> math) {
  return hysteresis::SingleLaw(type, std::move(math));
}

using testing::HalfSinePulse;
constexpr double kMass = testing::kChopraMass, kStiffness = testing::kChopraStiffness;
const double kDamping = testing::kChopraDamping;

ResponseHistory Simulate(const structure::Structure& s, const Excitation& e, TimeGrid grid,
                         const NewmarkOptions& options, RunSummary* summary = nullptr) {
  ResponseHistory response;
  const RunSummary result = RunNewmark(s, e, grid, options, &response);
  EXPECT_TRUE(result.ok()) << result.message;
  if (summary) *summary = result;
  return response;
}

// Chopra's tables, row k at t = 0.1 k s.
constexpr const auto& kRows = testing::kChopraChapter5;

TEST(ChopraChapter5, CaseALinearAverageAndLinearAcceleration) {
  const auto sdof =
      structure::BuildSdof(kMass, kDamping, Single(LawType::kLinearSpring, {kStiffness})).structure;
  RunSummary average_summary;
  const auto average = Simulate(sdof, HalfSinePulse(), {0.1, 10},
                                NewmarkOptions::AverageAcceleration(), &average_summary);
  const auto linear =
      Simulate(sdof, HalfSinePulse(), {0.1, 10}, NewmarkOptions::LinearAcceleration());
  // A linear system's tangent never changes: full Newton factorises it once for the run.
  EXPECT_EQ(average_summary.newton_iterations, 10);
  EXPECT_EQ(average_summary.factorisations, 1);
  for (int k = 0; k <= 10; ++k) {
    EXPECT_NEAR(average.displacement(k, 0), kRows[k].u_average, 1e-4) << "t = " << kRows[k].t;
    EXPECT_NEAR(average.velocity(k, 0), kRows[k].v_average, 1e-3) << "t = " << kRows[k].t;
    EXPECT_NEAR(linear.displacement(k, 0), kRows[k].u_linear, 1e-4) << "t = " << kRows[k].t;
  }
}

TEST(ChopraChapter5, CaseBElastoplasticNewtonAndModifiedNewton) {
  const auto sdof =
      structure::BuildSdof(kMass, kDamping, Single(LawType::kElastoplastic, {kStiffness, 0.75}))
          .structure;
  NewmarkOptions modified;
  modified.newton = NewmarkOptions::Newton::kModifiedStep;
  RunSummary full_summary, modified_summary;
  const auto full = Simulate(sdof, HalfSinePulse(), {0.1, 10}, NewmarkOptions{}, &full_summary);
  const auto mnr = Simulate(sdof, HalfSinePulse(), {0.1, 10}, modified, &modified_summary);
  for (int k = 0; k <= 10; ++k) {
    EXPECT_NEAR(full.displacement(k, 0), kRows[k].u_elastoplastic, 2e-4) << "t = " << kRows[k].t;
    EXPECT_NEAR(full.law_force(k, 0), kRows[k].fs_elastoplastic, 2e-3) << "t = " << kRows[k].t;
    EXPECT_NEAR(mnr.displacement(k, 0), kRows[k].u_elastoplastic, 2e-4) << "t = " << kRows[k].t;
  }
  // The law is piecewise linear and the predictor (the committed acceleration carried through
  // the step) lands every step of this pulse on its branch: one solve a step, with either
  // iteration (both factorise at the predictor).
  EXPECT_EQ(full_summary.newton_iterations, 10);
  EXPECT_EQ(modified_summary.newton_iterations, 10);
  // The tangent is k on the elastic branch and 0 yielding (|fs| at the yield force, 7.5 kips):
  // full Newton factorises it at the first step and again only where a step's branch is not the
  // last step's.
  const auto yielding = [&](int k) { return std::abs(full.law_force(k, 0)) > 7.5 - 1e-6; };
  int branch_changes = 0;
  for (int k = 2; k <= 10; ++k) branch_changes += yielding(k) != yielding(k - 1);
  EXPECT_GE(branch_changes, 2);  // yields, and unloads before the pulse ends
  EXPECT_EQ(full_summary.factorisations, 1 + branch_changes);

  NewmarkOptions initial;
  initial.newton = NewmarkOptions::Newton::kModifiedInitial;
  initial.max_iterations = 200;  // linear convergence with the elastic tangent
  RunSummary initial_summary;
  const auto mnr0 = Simulate(sdof, HalfSinePulse(), {0.1, 10}, initial, &initial_summary);
  for (int k = 0; k <= 10; ++k) {
    EXPECT_NEAR(mnr0.displacement(k, 0), kRows[k].u_elastoplastic, 2e-4) << "t = " << kRows[k].t;
  }
  EXPECT_EQ(initial_summary.factorisations, 1);  // one factorisation for the whole run
}

// Chopra's SDOF on a Bouc-Wen law of initial stiffness k yielding at his 7.5 kips: smooth, its
// knee the sharper the larger nu.
structure::Structure BoucWenSdof(double nu) {
  return structure::BuildSdof(
             kMass, kDamping,
             Single(LawType::kBoucWen, {kStiffness, kStiffness / std::pow(7.5, nu), 0.5, 0.5, nu}))
      .structure;
}

// On the smooth law full Newton converges quadratically, modified Newton on the step's first
// tangent linearly, with one factorisation a step; both reach the same response.
ResponseHistory SmoothSdof(NewmarkOptions::Newton newton, RunSummary* summary) {
  NewmarkOptions options;
  options.newton = newton;
  return Simulate(BoucWenSdof(1.0), HalfSinePulse(), {0.1, 10}, options, summary);
}

TEST(Newmark, ModifiedNewtonFactorisesOnceAStepAndReachesFullNewtonsResponse) {
  RunSummary full_summary, modified_summary;
  const auto full = SmoothSdof(NewmarkOptions::Newton::kFull, &full_summary);
  const auto modified = SmoothSdof(NewmarkOptions::Newton::kModifiedStep, &modified_summary);
  ASSERT_TRUE(full_summary.ok() && modified_summary.ok());
  EXPECT_GT(modified_summary.newton_iterations, full_summary.newton_iterations);
  // Full Newton factorises at every iteration whose tangent is not the last one factorised: on
  // this law, more than once a step on average; modified Newton at most once a step.
  EXPECT_GT(full_summary.factorisations, 10);
  EXPECT_LE(modified_summary.factorisations, 10);
  EXPECT_LT(modified_summary.factorisations, modified_summary.newton_iterations);
  const double peak = full.displacement.col(0).cwiseAbs().maxCoeff();
  EXPECT_GT(peak, 1.0);  // well past the yield displacement, 0.75 in
  for (int k = 0; k <= 10; ++k) {
    EXPECT_NEAR(modified.displacement(k, 0), full.displacement(k, 0), 1e-8 * peak) << "step " << k;
  }
}

TEST(Newmark, ElastoplasticPeakConvergesToChoprasFineStepValue) {
  // Chopra Ex. 5.5 recomputed with dt = 0.001 s: the converged peak is 2.2338 in at t = 0.690 s.
  const auto sdof =
      structure::BuildSdof(kMass, kDamping, Single(LawType::kElastoplastic, {kStiffness, 0.75}))
          .structure;
  const auto response = Simulate(sdof, HalfSinePulse(0.001), {0.001, 1000}, NewmarkOptions{});
  Eigen::Index peak = 0;
  response.displacement.col(0).maxCoeff(&peak);
  EXPECT_NEAR(response.displacement(peak, 0), 2.2338, 1e-4);
  EXPECT_NEAR(response.time[peak], 0.690, 1e-3);
}

// Damped SDOF from rest under p0 sin(W t): closed form (Chopra Sec. 3.2).
double HarmonicResponse(double t, double m, double k, double zeta, double p0, double big_omega) {
  const double w = std::sqrt(k / m), wd = w * std::sqrt(1 - zeta * zeta), r = big_omega / w;
  const double denominator = (1 - r * r) * (1 - r * r) + (2 * zeta * r) * (2 * zeta * r);
  const double c = p0 / k * (1 - r * r) / denominator, d = p0 / k * (-2 * zeta * r) / denominator;
  const double a = -d, b = (zeta * w * a - big_omega * c) / wd;
  return std::exp(-zeta * w * t) * (a * std::cos(wd * t) + b * std::sin(wd * t)) +
         c * std::sin(big_omega * t) + d * std::cos(big_omega * t);
}

TEST(Newmark, ConvergesAtSecondOrderOnALinearSdof) {
  const double m = 1.0, k = 4.0 * std::numbers::pi * std::numbers::pi, zeta = 0.05;
  const double big_omega = 2.0 * std::numbers::pi * 0.7, duration = 4.0;
  const auto sdof =
      structure::BuildSdof(m, 2 * zeta * std::sqrt(k * m), Single(LawType::kLinearSpring, {k}))
          .structure;
  std::vector<double> errors;
  for (const double dt : {0.02, 0.01, 0.005, 0.0025}) {
    const int steps = static_cast<int>(std::round(duration / dt));
    Excitation excitation;
    AppliedForce force{0, {dt / 4, {}}};  // sampled finer than dt: the load is exact at steps
    for (int i = 0; i <= 4 * steps; ++i)
      force.force.values.push_back(std::sin(big_omega * i * dt / 4));
    excitation.forces.push_back(force);
    const auto response = Simulate(sdof, excitation, {dt, steps}, NewmarkOptions{});
    double error = 0.0;
    for (int i = 0; i <= steps; ++i) {
      error = std::max(error, std::abs(response.displacement(i, 0) -
                                       HarmonicResponse(i * dt, m, k, zeta, 1.0, big_omega)));
    }
    errors.push_back(error);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    EXPECT_NEAR(std::log2(errors[i - 1] / errors[i]), 2.0, 0.1) << "dt halving " << i;
  }
}

TEST(Newmark, EnergyBalancesForAHystereticSdofUnderAPulse) {
  const auto sdof =
      structure::BuildSdof(kMass, kDamping, Single(LawType::kThm1, {10.0, 2.0, 4.5, 0.5, 1.5}))
          .structure;
  RunSummary summary;
  const auto response =
      Simulate(sdof, HalfSinePulse(0.001), {0.001, 3000}, NewmarkOptions{}, &summary);
  const Energies& end = response.energies.back();
  EXPECT_GT(end.hysteretic, 0.1 * end.input);
  EXPECT_LT(summary.energy_balance_error, 1e-3);
}

// Sampled finely enough that every analysis step of `dt` sees the exact load.
Excitation SampledForce(double dt, int steps, const std::function<double(double)>& force) {
  Excitation excitation;
  AppliedForce applied{0, {dt, {}}};
  for (int i = 0; i <= steps; ++i) applied.force.values.push_back(force(i * dt));
  excitation.forces.push_back(applied);
  return excitation;
}

TEST(Newmark, AContinuedSlipTakesOneSolvePerStep) {
  // While an elastoplastic spring slips, the step's equations are linear (tangent 0), so one
  // solve from a predictor on the slip tangent ends the step; only steps where the phase changes
  // (stick to slip, or a reversal) need more. The phases are read from the response: the law's
  // force is exactly +-fs while it slips.
  const double uy = 0.75, fy = kStiffness * uy, dt = 0.01;
  const int steps = 1000;
  const auto sdof =
      structure::BuildSdof(kMass, kDamping, Single(LawType::kElastoplastic, {kStiffness, uy}))
          .structure;
  const Excitation harmonic = SampledForce(
      dt, steps, [](double t) { return 10.0 * std::sin(2.0 * std::numbers::pi * t / 1.3); });
  RunSummary summary;
  const auto response = Simulate(sdof, harmonic, {dt, steps}, NewmarkOptions{}, &summary);
  int continued_slips = 0, phase_changes = 0;
  for (int k = 1; k <= steps; ++k) {
    const bool slips = std::abs(response.law_force(k, 0)) == fy;
    const bool slipped = std::abs(response.law_force(k - 1, 0)) == fy;
    continued_slips += slips && slipped;
    phase_changes += slips != slipped;
  }
  EXPECT_GT(continued_slips, 300);
  EXPECT_LE(summary.newton_iterations, steps + 2 * phase_changes)
      << continued_slips << " continued-slip steps, " << phase_changes << " phase changes";
}

TEST(Newmark, ReachesRoundOffInOneSolveWhereTheForceToleranceCannotBeMet) {
  // A linear SDOF with a 10 s period under a constant force at a fine step: the displacements
  // are large next to the forces, and rounding u alone leaves a residual of eps (4 m / h^2) u,
  // far above force_tolerance times the force scale. The equations are linear, so one solve per
  // step reaches the round-off floor; the response is the closed form u_st (1 - cos w t).
  const double m = 1.0, w = 2.0 * std::numbers::pi / 10.0, k = m * w * w, p0 = 1.0;
  const double dt = 1e-4;
  const int steps = 20000;
  const auto sdof = structure::BuildSdof(m, 0.0, Single(LawType::kLinearSpring, {k})).structure;
  RunSummary summary;
  const auto response = Simulate(sdof, SampledForce(dt, steps, [&](double) { return p0; }),
                                 {dt, steps}, NewmarkOptions{}, &summary);
  EXPECT_EQ(summary.newton_iterations, steps);
  const double u_static = p0 / k;
  for (int i = 0; i <= steps; i += 100) {
    EXPECT_NEAR(response.displacement(i, 0), u_static * (1.0 - std::cos(w * i * dt)),
                1e-9 * u_static)
        << "t = " << i * dt;
  }
}

TEST(Newmark, CutsAStepThatDoesNotConvergeAndReportsAFailureWithTime) {
  // Bouc-Wen with a sharp knee (nu = 20): linear to round-off well before its yield force of 7.5
  // kips, then smooth, so one correction leaves a residual far above the tolerance once it
  // yields, however small the step is cut. (A piecewise-linear law will not do: the predictor
  // lands its steps on the right branch.)
  const auto sdof = BoucWenSdof(20.0);
  NewmarkOptions options;
  options.max_iterations = 1;
  options.max_step_cuts = 2;
  ResponseHistory response;
  const RunSummary summary = RunNewmark(sdof, HalfSinePulse(), {0.1, 10}, options, &response);
  EXPECT_FALSE(summary.ok());
  EXPECT_GT(summary.step_cuts, 0);
  EXPECT_NE(summary.message.find("Newton did not converge at t = "), std::string::npos)
      << summary.message;
  EXPECT_EQ(response.rows_written, summary.steps + 1);
  EXPECT_GT(summary.steps, 0);  // the elastic steps before yield converged
  EXPECT_LT(summary.steps, 10);
}

TEST(NewmarkOptions, RejectsOutOfRangeFields) {
  NewmarkOptions options;
  options.beta = 0.0;
  EXPECT_THROW(options.Validate(), isolab::InvalidParameter);
  options = {};
  options.max_iterations = 0;
  EXPECT_THROW(options.Validate(), isolab::InvalidParameter);
}

}  // namespace
}  // namespace isolab::integrators
