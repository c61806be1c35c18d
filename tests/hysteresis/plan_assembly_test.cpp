// The plan assembly (plan_assembly.h): an uncoupled pair is exactly two independent 1-D laws; the
// assembly sums its components' forces, tangents and damping and their energies, the dashpots'
// share apart; a coupled slider's strength is a circle where the uncoupled pair's is a square
// (sqrt(2) fs along a diagonal); a law without a coupled form is refused; and Update allocates
// nothing (counted by this test's operator new).
#include "isolab/hysteresis/plan_assembly.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"

namespace {
long allocations = 0;  // operator new calls in this test binary
}  // namespace

void* operator new(std::size_t size) {
  ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace isolab::hysteresis {
namespace {

LawParameters Math(LawType type, std::vector<double> values) {
  return LawParameters::Make(type, ParameterForm::kMathematical, values);
}

// A curved displacement history (an ellipse that grows and turns), its rate, and time.
PlanLawInput At(int k) {
  const double t = 0.01 * k, a = 2.0 * k, theta = 0.05 * k;
  const Vec2 u{a * std::cos(theta), 0.6 * a * std::sin(theta + 0.3)};
  const Vec2 v{2.0 * std::cos(theta) - 0.05 * a * std::sin(theta),
               0.6 * (2.0 * std::sin(theta + 0.3) + 0.05 * a * std::cos(theta + 0.3))};
  return {u, (1.0 / 0.01) * v, t};
}

TEST(PlanAssembly, UncoupledPairIsTwoIndependentOneDirectionLaws) {
  const LawParameters along_x = Math(LawType::kThm1, {1, 0.2, 0.45, 20, 120});
  const LawParameters along_y =
      Math(LawType::kLeadRubber, {60, 1, 6, 100, 200, 1.456e-3, NAN, NAN, NAN, NAN});
  const PlanAssembly plan({{"pair", along_x, along_y}});
  const ParallelAssembly x({{"x", along_x}}), y({{"y", along_y}});
  std::vector<PlanLawState> committed(1), trial(1);
  std::vector<PlanLawResponse> responses(1);
  std::vector<LawState> cx(1), tx(1), cy(1), ty(1);
  std::vector<LawResponse> rx(1), ry(1);
  for (int k = 1; k <= 400; ++k) {
    const PlanLawInput in = At(k);
    const PlanResponse total = plan.Update(committed, in, trial, responses);
    const AssemblyResponse ax = x.Update(cx, {in.u.x, in.v.x, in.t}, tx, rx);
    const AssemblyResponse ay = y.Update(cy, {in.u.y, in.v.y, in.t}, ty, ry);
    ASSERT_EQ(total.force.x, ax.force);
    ASSERT_EQ(total.force.y, ay.force);
    ASSERT_EQ(total.stiffness.xx, ax.stiffness);
    ASSERT_EQ(total.stiffness.yy, ay.stiffness);
    ASSERT_EQ(total.stiffness.xy, 0.0);
    ASSERT_EQ(total.stiffness.yx, 0.0);
    ASSERT_EQ(trial[0].x.slider, tx[0].slider);
    ASSERT_EQ(trial[0].y.temperature, ty[0].temperature);
    ASSERT_EQ(plan.DissipatedEnergy(trial), x.DissipatedEnergy(tx) + y.DissipatedEnergy(ty));
    ASSERT_EQ(plan.StoredEnergy(trial), x.StoredEnergy(tx) + y.StoredEnergy(ty));
    std::swap(committed, trial);
    std::swap(cx, tx);
    std::swap(cy, ty);
  }
  EXPECT_GT(committed[0].y.temperature, 1.0);  // the y law's lead core did heat
}

TEST(PlanAssembly, SumsItsComponentsAndSplitsTheDashpotsEnergy) {
  const std::vector<PlanComponent> components = {
      {"bhm2", Math(LawType::kBhm2, {1, 0.2, 20}), std::nullopt},
      {"dashpot", Math(LawType::kDashpot, {0.02}), std::nullopt},
      {"pendulum", Math(LawType::kFrictionPendulum, {1000, 2000, 2, NAN, 0.03, 0.09, 0.02}),
       std::nullopt},
      {"pair", Math(LawType::kDashpot, {0.05}), Math(LawType::kBhm1, {1, 0.2, 20})},
  };
  const PlanAssembly assembly(components);
  ASSERT_EQ(assembly.size(), 4u);
  std::vector<PlanLawState> committed(4), trial(4), alone(4);
  std::vector<PlanLawResponse> responses(4);
  for (int k = 1; k <= 300; ++k) {
    const PlanLawInput in = At(k);
    const PlanResponse total = assembly.Update(committed, in, trial, responses);
    PlanResponse sum;
    for (std::size_t i = 0; i < 4; ++i) {
      PlanLawResponse r;
      UpdatePlanLaw(assembly.kernels()[i], committed[i], in, &alone[i], &r);
      sum.force = sum.force + r.force;
      sum.stiffness = sum.stiffness + r.stiffness;
      sum.damping = sum.damping + r.damping;
    }
    ASSERT_EQ(total.force.x, sum.force.x);
    ASSERT_EQ(total.force.y, sum.force.y);
    ASSERT_EQ(total.stiffness.xy, sum.stiffness.xy);
    ASSERT_EQ(total.damping.yx, sum.damping.yx);
    ASSERT_EQ(total.damping.yy, sum.damping.yy);
    std::swap(committed, trial);
  }
  // Dashpots: the coupled one and the pair's x law.
  EXPECT_EQ(assembly.ViscousEnergy(committed),
            Dissipated(committed[1]) + committed[3].x.dissipated);
  EXPECT_EQ(assembly.DissipatedEnergy(committed),
            Dissipated(committed[0]) + Dissipated(committed[1]) + Dissipated(committed[2]) +
                Dissipated(committed[3]));
  EXPECT_GT(assembly.ViscousEnergy(committed), 0.0);
  EXPECT_GT(assembly.DissipatedEnergy(committed), assembly.ViscousEnergy(committed));
}

TEST(PlanAssembly, CoupledStrengthIsACircleTheUncoupledPairsASquare) {
  // Elastoplastic, ke = 10, fs = 5, pushed far along the diagonal.
  const LawParameters law = Math(LawType::kElastoplastic, {10, 0.5});
  const PlanAssembly coupled({{"coupled", law, std::nullopt}});
  const PlanAssembly uncoupled({{"pair", law, law}});
  std::vector<PlanLawState> committed(1), trial(1);
  std::vector<PlanLawResponse> responses(1);
  const Vec2 diagonal{std::sqrt(0.5), std::sqrt(0.5)};
  const PlanLawInput far{20.0 * diagonal, {}, 0.0};
  EXPECT_NEAR(Norm(coupled.Update(committed, far, trial, responses).force), 5.0, 1e-12);
  EXPECT_NEAR(Norm(uncoupled.Update(committed, far, trial, responses).force), 5.0 * std::sqrt(2.0),
              1e-12);
  // Along an axis both carry fs.
  const PlanLawInput along_y{{0.0, 20.0}, {}, 0.0};
  EXPECT_NEAR(coupled.Update(committed, along_y, trial, responses).force.y, 5.0, 1e-12);
  EXPECT_NEAR(uncoupled.Update(committed, along_y, trial, responses).force.y, 5.0, 1e-12);
}

TEST(PlanAssembly, RefusesALawWithoutACoupledFormButTakesItUncoupled) {
  const LawParameters degrading = Math(LawType::kDegradingBhm2, {1, 0.2, 20, 0.4, 300});
  EXPECT_THROW(PlanAssembly({{"bearing", degrading, std::nullopt}}), std::invalid_argument);
  EXPECT_NO_THROW(PlanAssembly({{"bearing", degrading, degrading}}));
}

TEST(PlanAssembly, UpdateAllocatesNothing) {
  const PlanAssembly assembly({
      {"thm1", Math(LawType::kThm1, {1, 0.2, 0.45, 20, 120}), std::nullopt},
      {"thm2", Math(LawType::kThm2, {1, 0.2, 0.05, 20, 120}), std::nullopt},
      {"bouc_wen", Math(LawType::kBoucWen, {1.0, 0.05, 0.5, 0.5, 1.0}), std::nullopt},
      {"lead", Math(LawType::kLeadRubber, {60, 1, 6, 100, 200, 1.456e-3, 0.05, 14.1, 60, NAN}),
       std::nullopt},
      {"pair", Math(LawType::kBhm2, {1, 0.2, 20}),
       Math(LawType::kDegradingBhm2, {1, 0.2, 20, 0.4, 300})},
  });
  std::vector<PlanLawState> committed(assembly.size()), trial(assembly.size());
  std::vector<PlanLawResponse> responses(assembly.size());
  const long before = allocations;
  double sum = 0.0;
  for (int k = 1; k <= 2000; ++k) {
    sum += assembly.Update(committed, At(k), trial, responses).force.x;
    std::swap(committed, trial);
  }
  EXPECT_EQ(allocations, before);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
}  // namespace isolab::hysteresis
