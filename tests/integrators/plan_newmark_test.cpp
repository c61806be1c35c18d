// Newmark on buildings in plan (plan_building.h, structure.h):
//  * the tangent of an eccentric building on coupled, uncoupled and linear isolators against
//    central differences of its force, in every phase the sliders pass through;
//  * a symmetric plan building under one component equals the one-direction building
//    (shear_building.h) to round-off, on coupled and on uncoupled isolators;
//  * an eccentric linear building against its modal solution: a dense eigensolution of (K, M),
//    K written out in the test from the rigid-floor kinematics, and each mode's exact response to
//    the piecewise-linear record (Nigam-Jennings, exact_linear_sdof.h), which shares no code with
//    Newmark.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <vector>

#include "isolab/integrators/newmark.h"
#include "isolab/spectra/exact_linear_sdof.h"
#include "isolab/structure/plan_building.h"
#include "isolab/structure/shear_building.h"

namespace isolab::integrators {
namespace {

using hysteresis::LawParameters;
using hysteresis::LawType;
using hysteresis::ParallelAssembly;
using hysteresis::ParameterForm;
using hysteresis::PlanAssembly;
using hysteresis::Vec2;
using structure::PlanBuilding;

constexpr double kPi = std::numbers::pi;

// kN, mm, s. Masses in kN s^2/mm (1 t = 1e-3).
LawParameters Bilinear(double scale) {
  const double values[] = {scale * 8.0, scale * 1.0, 20.0};  // k0, k1, uy
  return LawParameters::Make(LawType::kBhm2, ParameterForm::kMathematical, values);
}
ParallelAssembly Linear(double k) { return hysteresis::SingleLaw(LawType::kLinearSpring, {k}); }

// A ground acceleration with two frequencies (mm/s^2, peak about 0.3 g), 6 s at 0.01 s.
SampledHistory Shaking(double amplitude, double f1, double f2) {
  SampledHistory history{0.01, {}};
  for (int k = 0; k <= 600; ++k) {
    const double t = 0.01 * k;
    history.values.push_back(amplitude * std::sin(kPi * t / 6) *
                             (std::sin(2 * kPi * f1 * t) + 0.5 * std::sin(2 * kPi * f2 * t)));
  }
  return history;
}

// `stories` floors of 100 t on a 20 m x 12 m plan (mm), four isolators at the corners sharing
// `isolation` per unit scale; centres of mass at `offset` from the plan's centre.
PlanBuilding Building(int stories, bool uncoupled, Vec2 mass_offset, Vec2 stiffness_offset,
                      bool linear_isolators = false) {
  const Vec2 centre{10000.0, 6000.0};
  const double mass = 0.1;
  const double inertia = mass * (20000.0 * 20000.0 + 12000.0 * 12000.0) / 12.0;
  PlanBuilding building;
  building.base = {mass, inertia, centre + mass_offset};
  for (int s = 0; s < stories; ++s) {
    structure::PlanStory story;
    story.name = "s" + std::to_string(s + 1);
    story.floor = {mass, inertia, centre + mass_offset};
    story.centre_of_stiffness = centre + stiffness_offset;
    story.x = Linear(120.0);
    story.y = Linear(120.0);
    story.torsion = Linear(120.0 * 6000.0 * 6000.0);
    building.stories.push_back(story);
  }
  for (const Vec2 corner : {Vec2{0, 0}, Vec2{20000, 0}, Vec2{0, 12000}, Vec2{20000, 12000}}) {
    hysteresis::PlanComponent component{"bearing", Bilinear(0.25), std::nullopt};
    if (linear_isolators) {
      const double k = 0.25 * 2.5;
      component.law = LawParameters::Make(LawType::kLinearSpring, ParameterForm::kMathematical,
                                          std::vector<double>{k});
    }
    if (uncoupled) component.law_y = component.law;
    building.isolators.push_back({"corner", corner, PlanAssembly({component})});
  }
  return building;
}

// The same building in one direction: four quarter isolators summed, stories along x.
structure::Structure OneDirection(int stories) {
  structure::ShearBuilding building;
  building.isolated = true;
  building.base_mass = 0.1;
  building.isolation = ParallelAssembly(
      {{"a", Bilinear(0.25)}, {"b", Bilinear(0.25)}, {"c", Bilinear(0.25)}, {"d", Bilinear(0.25)}});
  for (int s = 0; s < stories; ++s) building.stories.push_back({"s", 0.1, 3000, Linear(120.0)});
  return structure::BuildShearBuilding(building).structure;
}

// The stiffness of Building(stories, false, mass_offset, stiffness_offset, true), dense and
// written out here from the rigid-floor kinematics: a point p of floor f moves by
// (u_x - (p_y - c_y) theta, u_y + (p_x - c_x) theta), c the floor's centre of mass.
Eigen::MatrixXd LinearStiffness(int stories, Vec2 mass_offset, Vec2 stiffness_offset) {
  const int n = 3 * (stories + 1);
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  const auto add = [&](const Eigen::VectorXd& a, double stiffness) {
    k += stiffness * a * a.transpose();
  };
  const Vec2 e = stiffness_offset - mass_offset;  // centre of stiffness from the centre of mass
  for (int s = 0; s < stories; ++s) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n), y = x, twist = x;
    for (const auto& [floor, sign] : {std::pair{s, -1.0}, std::pair{s + 1, 1.0}}) {
      x[3 * floor] = sign;
      x[3 * floor + 2] = -sign * e.y;
      y[3 * floor + 1] = sign;
      y[3 * floor + 2] = sign * e.x;
      twist[3 * floor + 2] = sign;
    }
    add(x, 120.0);
    add(y, 120.0);
    add(twist, 120.0 * 6000.0 * 6000.0);
  }
  const Vec2 centre = Vec2{10000.0, 6000.0} + mass_offset;
  for (const Vec2 corner : {Vec2{0, 0}, Vec2{20000, 0}, Vec2{0, 12000}, Vec2{20000, 12000}}) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n), y = x;
    x[0] = 1.0;
    x[2] = -(corner.y - centre.y);
    y[1] = 1.0;
    y[2] = corner.x - centre.x;
    add(x, 0.25 * 2.5);
    add(y, 0.25 * 2.5);
  }
  return k;
}

TEST(PlanBuilding, TangentMatchesCentralDifferencesOfTheForce) {
  // Coupled and uncoupled bilinear isolators, and linear ones, whose terms (as the stories') only
  // ConstantTangent writes.
  for (const auto& [uncoupled, linear] : {std::pair{false, false}, {true, false}, {false, true}}) {
    PlanBuilding description = Building(2, uncoupled, {400, -300}, {-500, 200}, linear);
    description.damping = {true, {1.0, 0.2}, {0.05, 0.05}};
    const structure::Structure s = structure::BuildPlanBuilding(description).structure;
    const int n = s.dofs();
    std::vector<hysteresis::LawState> committed(s.law_count()), trial(s.law_count());
    std::vector<hysteresis::LawResponse> responses(s.law_count());
    std::vector<double> forces(s.force_columns());
    Eigen::VectorXd u(n), v(n), f(n), f_plus(n), f_minus(n);
    // Past yield on some isolators, elastic on others; then a committed state to start from.
    for (const double amplitude : {5.0, 60.0}) {
      for (int i = 0; i < n; ++i) {
        u[i] = amplitude * std::sin(1.0 + i) * (i % 3 == 2 ? 1e-4 : 1.0);
        v[i] = 30.0 * std::cos(2.0 + i) * (i % 3 == 2 ? 1e-4 : 1.0);
      }
      structure::SparseMatrix tangent = s.tangent_pattern();
      const structure::TangentFactors factors{0.0, 0.7};
      s.ConstantTangent(factors, &tangent);
      s.Evaluate(committed, 0.0, u, v, trial, responses, &f, forces, factors, &tangent);
      const Eigen::MatrixXd k(tangent);
      for (int j = 0; j < n; ++j) {
        const double h = (j % 3 == 2 ? 1e-4 : 1.0) * 1e-4;
        Eigen::VectorXd up = u, um = u, vp = v, vm = v;
        up[j] += h;
        um[j] -= h;
        vp[j] += factors.damping * h;  // d/du of (f(u, v)) + c1 d/dv, along one direction
        vm[j] -= factors.damping * h;
        s.Evaluate(committed, 0.0, up, vp, trial, responses, &f_plus, forces, factors, nullptr);
        s.Evaluate(committed, 0.0, um, vm, trial, responses, &f_minus, forces, factors, nullptr);
        const Eigen::VectorXd column = (f_plus - f_minus) / (2 * h);
        EXPECT_LE((column - k.col(j)).cwiseAbs().maxCoeff(),
                  1e-6 * std::max(1.0, k.col(j).cwiseAbs().maxCoeff()))
            << "uncoupled " << uncoupled << ", linear " << linear << ", amplitude " << amplitude
            << ", column " << j;
      }
      s.Evaluate(committed, 0.0, u, v, trial, responses, &f, forces, factors, nullptr);
      committed = trial;
    }
  }
}

TEST(PlanNewmark, SymmetricBuildingUnderOneComponentEqualsTheOneDirectionModel) {
  const SampledHistory record = Shaking(3000.0, 0.4, 1.7);
  const TimeGrid grid{0.005, 1200, 1};
  ResponseHistory one;
  ASSERT_TRUE(RunNewmark(OneDirection(3), Excitation::Uniform(record), grid, {}, &one).ok());
  const double peak = one.displacement.col(0).cwiseAbs().maxCoeff();
  ASSERT_GT(peak, 60.0);  // well past the isolators' yield (20 mm)
  for (const bool uncoupled : {false, true}) {
    const structure::LaidOutStructure plan =
        structure::BuildPlanBuilding(Building(3, uncoupled, {}, {}));
    ResponseHistory two;
    ASSERT_TRUE(
        RunNewmark(plan.structure, Excitation::Horizontal(plan.layout, record), grid, {}, &two)
            .ok());
    for (int floor = 0; floor < 4; ++floor) {
      const double error =
          (two.displacement.col(3 * floor) - one.displacement.col(floor)).cwiseAbs().maxCoeff();
      EXPECT_LE(error, 1e-10 * peak) << "uncoupled " << uncoupled << ", floor " << floor;
      EXPECT_EQ(two.displacement.col(3 * floor + 1).cwiseAbs().maxCoeff(), 0.0);
      EXPECT_EQ(two.displacement.col(3 * floor + 2).cwiseAbs().maxCoeff(), 0.0);
    }
    const Energies& a = one.energies.back();
    const Energies& b = two.energies.back();
    EXPECT_NEAR(b.input, a.input, 1e-9 * a.input);
    EXPECT_NEAR(b.hysteretic, a.hysteretic, 1e-9 * a.input);
  }
}

TEST(PlanNewmark, EccentricLinearBuildingMatchesItsModalSolution) {
  const structure::LaidOutStructure laid_out =
      structure::BuildPlanBuilding(Building(2, false, {800, -500}, {-600, 300}, true));
  const structure::Structure& plan = laid_out.structure;
  const int n = plan.dofs();
  const Eigen::MatrixXd k = LinearStiffness(2, {800, -500}, {-600, 300});
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(
      k, Eigen::MatrixXd(plan.mass().asDiagonal()));
  ASSERT_EQ(modes.info(), Eigen::Success);

  // Two components at 30 degrees to the axes, different spectra.
  const SampledHistory h1 = Shaking(2500.0, 0.45, 1.3), h2 = Shaking(1800.0, 0.6, 2.2);
  const double angle = kPi / 6;
  SampledHistory x = h1, y = h2;
  for (std::size_t k = 0; k < h1.values.size(); ++k) {
    x.values[k] = std::cos(angle) * h1.values[k] - std::sin(angle) * h2.values[k];
    y.values[k] = std::sin(angle) * h1.values[k] + std::cos(angle) * h2.values[k];
  }
  const Excitation excitation = Excitation::Horizontal(laid_out.layout, x, y);
  // Modal superposition: q_n'' + w_n^2 q_n = -phi_n^T M (r_x a_gx + r_y a_gy), exact per step.
  const int samples = static_cast<int>(h1.values.size());
  Eigen::MatrixXd exact = Eigen::MatrixXd::Zero(samples, n);
  for (int mode = 0; mode < n; ++mode) {
    const Eigen::VectorXd phi = modes.eigenvectors().col(mode);
    double gx = 0.0, gy = 0.0;  // participation of each component
    for (int i = 0; i < n; i += 3) {
      gx += phi[i] * plan.mass()[i];
      gy += phi[i + 1] * plan.mass()[i + 1];
    }
    const double w = std::sqrt(modes.eigenvalues()[mode]);
    const auto c = spectra::ExactStepCoefficients::For(w, 0.0, 0.01);
    double q = 0.0, q_rate = 0.0;
    for (int k = 1; k < samples; ++k) {
      const double p0 = -(gx * x.values[k - 1] + gy * y.values[k - 1]);
      const double p1 = -(gx * x.values[k] + gy * y.values[k]);
      const double q_next = c.a * q + c.b * q_rate + c.c * p0 + c.d * p1;
      q_rate = c.a_v * q + c.b_v * q_rate + c.c_v * p0 + c.d_v * p1;
      q = q_next;
      exact.row(k) += q * phi.transpose();
    }
  }
  // Newmark at a step 20 times finer than the record (its period error is second order).
  ResponseHistory response;
  ASSERT_TRUE(RunNewmark(plan, excitation, {0.0005, 12000, 20}, {}, &response).ok());
  ASSERT_EQ(response.rows_written, samples);
  for (int i = 0; i < n; ++i) {
    const double peak = exact.col(i).cwiseAbs().maxCoeff();
    ASSERT_GT(peak, 0.0);
    const Eigen::VectorXd newmark = response.displacement.col(i);
    EXPECT_LE((newmark - exact.col(i)).cwiseAbs().maxCoeff(), 2e-4 * peak) << "dof " << i;
  }
  // The eccentricity twists the base: its rotation is not small against the translations.
  EXPECT_GT(exact.col(2).cwiseAbs().maxCoeff() * 10000.0,
            0.05 * exact.col(0).cwiseAbs().maxCoeff());
}

}  // namespace
}  // namespace isolab::integrators
