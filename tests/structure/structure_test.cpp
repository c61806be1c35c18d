// Structure's effective tangent, ConstantTangent's terms plus what Evaluate adds, against central
// differences of Evaluate's force: members whose laws have a constant tangent (a linear spring, a
// trilinear spring with kh1 = kh2 and a finite corner, a dashpot), which only ConstantTangent
// writes, beside ones that do not (a bilinear isolator, a trilinear spring), grounded and between
// dofs, a member on a combination of three dofs and a coupled law on a 2-vector map of them, with
// viscous damping.
#include "isolab/structure/structure.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "isolab/hysteresis/law_parameters.h"

namespace isolab::structure {
namespace {

using hysteresis::LawParameters;
using hysteresis::LawType;
using hysteresis::ParallelAssembly;
using hysteresis::ParameterForm;

LawParameters Law(LawType type, std::vector<double> mathematical) {
  return LawParameters::Make(type, ParameterForm::kMathematical, mathematical);
}

Structure ThreeDofs() {
  std::vector<Member> connections;
  connections.push_back(
      Member::Between("isolator", kGround, 0,
                      ParallelAssembly({{"slider", Law(LawType::kBhm1, {8.0, 1.0, 20.0})},
                                        {"dashpot", Law(LawType::kDashpot, {0.3})}})));
  connections.push_back(Member::Between(
      "linear story", 0, 1, ParallelAssembly({{"k", Law(LawType::kLinearSpring, {120.0})}})));
  // kh1 = kh2 with a corner at 5: constant although the law is trilinear in form.
  connections.push_back(
      Member::Between("straight trilinear story", 1, 2,
                      ParallelAssembly({{"k", Law(LawType::kTrilinearElastic, {90.0, 90.0, 5.0})},
                                        {"c", Law(LawType::kDashpot, {0.1})}})));
  connections.push_back(Member::Between(
      "trilinear brace", 0, 2,
      ParallelAssembly({{"k", Law(LawType::kTrilinearElastic, {40.0, 4.0, 5.0})}})));
  // A member on a weighted combination of three dofs (as a story of a building in plan acts on
  // translations and rotations), yielding, beside the springs between two dofs.
  Member combined;
  combined.name = "combined";
  combined.dofs = {0, 1, 2, kGround, kGround, kGround};
  combined.coefficients = {-0.7, 1.3, 0.4, 0.0, 0.0, 0.0};
  combined.assembly = ParallelAssembly({{"k", Law(LawType::kBhm2, {30.0, 3.0, 2.0})}});
  connections.push_back(combined);
  const std::vector<Eigen::Triplet<double>> c{
      {0, 0, 0.5}, {1, 1, 0.7}, {0, 1, -0.2}, {1, 0, -0.2}, {2, 2, 0.4}};
  SparseMatrix damping(3, 3);
  damping.setFromTriplets(c.begin(), c.end());
  // A coupled law on the deformation vector (u_0 - 0.5 u_2, u_1 + 0.8 u_2), as an isolator under
  // a floor's (u_x, u_y, theta).
  CoupledMember coupled;
  coupled.name = "coupled";
  coupled.dofs = {0, 1, 2, kGround, kGround, kGround};
  coupled.columns = {Vec2{1.0, 0.0}, Vec2{0.0, 1.0}, Vec2{-0.5, 0.8}, Vec2{}, Vec2{}, Vec2{}};
  coupled.assembly =
      hysteresis::PlanAssembly({{"slider", Law(LawType::kBhm2, {20.0, 2.0, 4.0}), std::nullopt},
                                {"dashpot", Law(LawType::kDashpot, {0.2}), std::nullopt}});
  // And one on any 2 x 2 map of two dofs (the tangent's general path).
  CoupledMember skew;
  skew.name = "skew";
  skew.dofs = {2, 0, kGround, kGround, kGround, kGround};
  skew.columns = {Vec2{0.6, 0.2}, Vec2{-0.3, 1.0}, Vec2{}, Vec2{}, Vec2{}, Vec2{}};
  skew.assembly =
      hysteresis::PlanAssembly({{"slider", Law(LawType::kBhm2, {15.0, 1.5, 3.0}), std::nullopt}});
  return Structure(Eigen::Vector3d(0.1, 0.2, 0.3), std::move(connections), {coupled, skew},
                   damping);
}

TEST(Structure, ConstantTangentPlusEvaluateIsTheDerivativeOfTheForce) {
  const Structure s = ThreeDofs();
  std::vector<hysteresis::LawState> committed(s.law_count()), trial(s.law_count());
  std::vector<hysteresis::LawResponse> responses(s.law_count());
  std::vector<double> forces(s.force_columns());
  const TangentFactors factors{40.0, 0.7};
  Eigen::VectorXd f(3), f_plus(3), f_minus(3);
  // Elastic everywhere, then past the isolator's yield (20 mm) and both trilinear corners.
  for (const Eigen::Vector3d& u :
       {Eigen::Vector3d(1.0, 2.5, 3.0), Eigen::Vector3d(30.0, 32.0, 41.0)}) {
    const Eigen::VectorXd v = Eigen::Vector3d(20.0, -15.0, 10.0);
    SparseMatrix tangent = s.tangent_pattern();
    s.ConstantTangent(factors, &tangent);
    s.Evaluate(committed, 0.0, u, v, trial, responses, &f, forces, factors, &tangent);
    const Eigen::MatrixXd k(tangent);
    // The force has no mass term: d/du of f(u, v(u)) with dv/du = factors.damping.
    const Eigen::MatrixXd expected_mass =
        factors.mass * Eigen::Vector3d(0.1, 0.2, 0.3).asDiagonal();
    for (int j = 0; j < 3; ++j) {
      const double h = 1e-5;
      Eigen::VectorXd up = u, um = u, vp = v, vm = v;
      up[j] += h;
      um[j] -= h;
      vp[j] += factors.damping * h;
      vm[j] -= factors.damping * h;
      s.Evaluate(committed, 0.0, up, vp, trial, responses, &f_plus, forces, factors, nullptr);
      s.Evaluate(committed, 0.0, um, vm, trial, responses, &f_minus, forces, factors, nullptr);
      const Eigen::VectorXd column = (f_plus - f_minus) / (2 * h) + expected_mass.col(j);
      EXPECT_LE((column - k.col(j)).cwiseAbs().maxCoeff(), 1e-6 * k.col(j).cwiseAbs().maxCoeff())
          << "at u = " << u.transpose() << ", column " << j;
    }
  }
}

// Every member and coupled member through the one slot interface, against the deformations
// written out from the members' definitions in ThreeDofs; the slots' forces, mapped back through
// their influences, are the resisting force Evaluate returns less the viscous C v.
TEST(Structure, SlotsAreTheMembersAndCoupledMembersThroughOneInterface) {
  const Structure s = ThreeDofs();
  ASSERT_EQ(s.slots(), 7u);
  const Eigen::Vector3d u(1.5, -2.0, 0.25);
  const double u0 = u[0], u1 = u[1], u2 = u[2];
  const std::vector<Vec2> expected{{u0, 0.0},
                                   {u1 - u0, 0.0},
                                   {u2 - u1, 0.0},
                                   {u2 - u0, 0.0},
                                   {-0.7 * u0 + 1.3 * u1 + 0.4 * u2, 0.0},
                                   {u0 - 0.5 * u2, u1 + 0.8 * u2},
                                   {0.6 * u2 - 0.3 * u0, 0.2 * u2 + 1.0 * u0}};
  const std::vector<std::string> names{
      "isolator", "linear story", "straight trilinear story", "trilinear brace", "combined",
      "coupled",  "skew"};
  const std::vector<std::size_t> components{2, 1, 2, 1, 1, 2, 1};
  const std::vector<std::size_t> force_columns{0, 1, 2, 3, 4, 5, 7};
  const std::span<const double> dofs(u.data(), 3);
  for (std::size_t slot = 0; slot < s.slots(); ++slot) {
    SCOPED_TRACE(names[slot]);
    const int width = slot < 5 ? 1 : 2;
    EXPECT_EQ(s.slot_width(slot), width);
    EXPECT_EQ(s.slot_name(slot), names[slot]);
    EXPECT_EQ(s.slot_force_column(slot), force_columns[slot]);
    const Vec2 d = s.SlotDeformation(slot, dofs);
    EXPECT_NEAR(d.x, expected[slot].x, 1e-14);
    EXPECT_NEAR(d.y, expected[slot].y, 1e-14);
    const Structure::Influence influence = s.SlotInfluence(slot);
    Vec2 mapped;
    for (int a = 0; a < influence.count; ++a) {
      mapped = mapped + u[influence.dofs[a]] * influence.columns[a];
    }
    EXPECT_NEAR(mapped.x, expected[slot].x, 1e-14);
    EXPECT_NEAR(mapped.y, expected[slot].y, 1e-14);
    const std::size_t count = s.VisitSlotAssembly(
        slot, [](const auto& assembly) { return assembly.components().size(); });
    EXPECT_EQ(count, components[slot]);
    const std::size_t next = slot + 1 < s.slots() ? s.slot_law_offset(slot + 1) : s.law_count();
    EXPECT_EQ(next - s.slot_law_offset(slot), width * components[slot]);
  }

  std::vector<hysteresis::LawState> committed(s.law_count()), trial(s.law_count());
  std::vector<hysteresis::LawResponse> responses(s.law_count());
  std::vector<double> forces(s.force_columns());
  const Eigen::Vector3d v(20.0, -15.0, 10.0);
  Eigen::VectorXd f(3), viscous(3);
  s.Evaluate(committed, 0.0, u, v, trial, responses, &f, forces, {}, nullptr);
  s.DampingForce(v, &viscous);
  Eigen::Vector3d from_slots = viscous;
  for (std::size_t slot = 0; slot < s.slots(); ++slot) {
    const Vec2 force = s.SlotForce(slot, forces);
    if (s.slot_width(slot) == 1) {
      EXPECT_EQ(force.y, 0.0);
    }
    const Structure::Influence influence = s.SlotInfluence(slot);
    for (int a = 0; a < influence.count; ++a) {
      from_slots[influence.dofs[a]] +=
          influence.columns[a].x * force.x + influence.columns[a].y * force.y;
    }
  }
  EXPECT_LE((from_slots - f).cwiseAbs().maxCoeff(), 1e-12 * f.cwiseAbs().maxCoeff());
}

// Three dofs with linear members (a grounded spring and dashpot, as a linear isolator; a story of
// three laws, one a trilinear spring with kh1 = kh2, so that their order of summation shows)
// beside ones that are not (a yielding story, a trilinear brace), with viscous damping.
Structure LinearAndNot() {
  std::vector<Member> members;
  members.push_back(Member::Between("linear isolator", kGround, 0,
                                    ParallelAssembly({{"k", Law(LawType::kLinearSpring, {50.0})},
                                                      {"c", Law(LawType::kDashpot, {0.4})}})));
  members.push_back(Member::Between(
      "three-law story", 0, 1,
      ParallelAssembly({{"k", Law(LawType::kLinearSpring, {123.456789})},
                        {"c", Law(LawType::kDashpot, {0.3183098861837907})},
                        {"straight", Law(LawType::kTrilinearElastic, {0.0911, 0.0911, 5.0})}})));
  members.push_back(
      Member::Between("yielding story", 1, 2,
                      ParallelAssembly({{"slider", Law(LawType::kBhm1, {8.0, 1.0, 20.0})},
                                        {"c", Law(LawType::kDashpot, {0.1})}})));
  members.push_back(Member::Between(
      "trilinear brace", 0, 2,
      ParallelAssembly({{"k", Law(LawType::kTrilinearElastic, {40.0, 4.0, 5.0})}})));
  const std::vector<Eigen::Triplet<double>> c{{0, 0, 0.5}, {1, 1, 0.7}, {2, 2, 0.4}};
  SparseMatrix damping(3, 3);
  damping.setFromTriplets(c.begin(), c.end());
  return Structure(Eigen::Vector3d(0.1, 0.2, 0.3), std::move(members), {}, damping);
}

bool SameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool SameState(const hysteresis::LawState& a, const hysteresis::LawState& b) {
  return SameBits(a.u, b.u) && SameBits(a.v, b.v) && SameBits(a.force, b.force) &&
         SameBits(a.slider, b.slider) && SameBits(a.accumulated_slip, b.accumulated_slip) &&
         SameBits(a.t, b.t) && SameBits(a.temperature, b.temperature) && a.slip == b.slip &&
         SameBits(a.dissipated, b.dissipated);
}
bool SameResponse(const hysteresis::LawResponse& a, const hysteresis::LawResponse& b) {
  return SameBits(a.force, b.force) && SameBits(a.stiffness, b.stiffness) &&
         SameBits(a.damping, b.damping);
}
bool SameValues(std::span<const double> a, std::span<const double> b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                            [](double x, double y) { return SameBits(x, y); });
}

// Evaluate with LinearLaws::kForceOnly gives the force, force columns and tangent that kUpdate
// gives, to the bit, writes every other law's trial state and response, and leaves the linear
// members' as they were; UpdateLinearLaws then writes those as kUpdate does, to the bit. From a
// committed state that is not at rest.
TEST(Structure, LinearLawsTakenForceOnlyAndUpdatedAtTheEndAreWhatEvaluateWrites) {
  const Structure s = LinearAndNot();
  const std::size_t laws = s.law_count();
  ASSERT_EQ(laws, 8u);
  const std::vector<bool> linear{true, true, true, true, true, false, false, false};
  const TangentFactors factors{40.0, 0.7};
  std::vector<hysteresis::LawState> committed(laws), scratch(laws);
  std::vector<hysteresis::LawResponse> responses(laws);
  std::vector<double> columns(s.force_columns());
  Eigen::VectorXd f(3);
  s.Evaluate(committed, 0.01, Eigen::Vector3d(12.0, 15.0, 36.0), Eigen::Vector3d(3.0, -1.0, 2.0),
             scratch, responses, &f, columns, factors, nullptr);
  committed = scratch;  // yielded and moving

  hysteresis::LawState untouched;
  untouched.u = untouched.v = untouched.force = untouched.dissipated = -7.25;
  const hysteresis::LawResponse unanswered{-7.25, -7.25, -7.25};
  // Trial states about the committed one: inside and beyond the straight trilinear's corner (5),
  // many, so that a sum of the three-law story's forces in another order would show in one.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> spread(-10.0, 10.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::VectorXd u =
        Eigen::Vector3d(12.0 + spread(random), 15.0 + spread(random), 36.0 + spread(random));
    const Eigen::VectorXd v = Eigen::Vector3d(spread(random), spread(random), spread(random));
    SCOPED_TRACE(::testing::Message() << "u = " << u.transpose() << ", v = " << v.transpose());
    std::vector<hysteresis::LawState> full(laws), deferred(laws, untouched);
    std::vector<hysteresis::LawResponse> full_responses(laws), deferred_responses(laws, unanswered);
    std::vector<double> full_columns(s.force_columns()), deferred_columns(s.force_columns());
    Eigen::VectorXd full_force(3), deferred_force(3);
    SparseMatrix full_tangent = s.tangent_pattern(), deferred_tangent = s.tangent_pattern();
    s.ConstantTangent(factors, &full_tangent);
    s.ConstantTangent(factors, &deferred_tangent);
    s.Evaluate(committed, 0.02, u, v, full, full_responses, &full_force, full_columns, factors,
               &full_tangent);
    s.Evaluate(committed, 0.02, u, v, deferred, deferred_responses, &deferred_force,
               deferred_columns, factors, &deferred_tangent, {}, Structure::LinearLaws::kForceOnly);
    EXPECT_TRUE(SameValues({full_force.data(), 3}, {deferred_force.data(), 3}));
    EXPECT_TRUE(SameValues(full_columns, deferred_columns));
    const auto nonzeros = static_cast<std::size_t>(full_tangent.nonZeros());
    EXPECT_TRUE(
        SameValues({full_tangent.valuePtr(), nonzeros}, {deferred_tangent.valuePtr(), nonzeros}));
    for (std::size_t l = 0; l < laws; ++l) {
      SCOPED_TRACE(::testing::Message() << "law " << l);
      EXPECT_TRUE(SameState(deferred[l], linear[l] ? untouched : full[l]));
      EXPECT_TRUE(SameResponse(deferred_responses[l], linear[l] ? unanswered : full_responses[l]));
    }
    s.UpdateLinearLaws(committed, 0.02, u, v, deferred, deferred_responses);
    for (std::size_t l = 0; l < laws; ++l) {
      SCOPED_TRACE(::testing::Message() << "law " << l << ", updated");
      EXPECT_TRUE(SameState(deferred[l], full[l]));
      EXPECT_TRUE(SameResponse(deferred_responses[l], full_responses[l]));
    }
  }
  // Scales (a pendulum's axial load) apply to every law's response: refused with force only.
  const std::vector<double> scales(s.slots(), 1.0);
  EXPECT_THROW(s.Evaluate(committed, 0.02, Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d::Zero(),
                          scratch, responses, &f, columns, factors, nullptr, scales,
                          Structure::LinearLaws::kForceOnly),
               std::invalid_argument);
}
}  // namespace
}  // namespace isolab::structure
