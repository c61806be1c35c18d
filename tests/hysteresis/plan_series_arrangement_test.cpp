// Sliders in series in plan (plan_series_arrangement.h), the double and triple pendulums with
// circular friction and restrainer rings: along any line through the origin the plan law is its
// 1-D law to round-off (force, tangent, elements, dissipated and stored energy); on curved paths
// its 2x2 tangent is the derivative of the update it computes; every element stays within its ring
// and its friction circle and dissipates its strength times its travel; and on a circular orbit
// its force and dissipation per revolution tend to the closed form of steady circular sliding:
//
// On a circle of radius A at constant angular speed every element slides round a circle of its
// own, of radius r_k, lagging the force by the angle alpha_k: along the ring its friction f_k
// balances the force's part across z_k, across it the pendulum (and the stop) the rest, so
//   sin alpha_k = f_k / |F|,   r_k = min(d_k, sqrt(|F|^2 - f_k^2) / k_k),
//   A^2 = (|F| / ke + sum_k r_k cos alpha_k)^2 + (sum_k r_k sin alpha_k)^2,
// which gives |F| for A, and the elements dissipate 2 pi sum_k f_k r_k a revolution. Beyond all
// regimes (every element against its ring) r_k = d_k: the dissipation 2 pi sum_k f_k d_k no longer
// depends on A.
#include "isolab/hysteresis/plan_series_arrangement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "isolab/hysteresis/law_parameters.h"
#include "isolab/hysteresis/multiple_pendulum.h"
#include "isolab/hysteresis/plan_assembly.h"
#include "isolab/hysteresis/plan_law_kernel.h"
#include "plan_law_cases.h"
#include "series_law_harness.h"

namespace isolab::hysteresis {
namespace {

constexpr double kPi = std::numbers::pi;

struct SeriesCase {
  std::string name;
  LawParameters parameters;
  double scale;  // reaches beyond every stop
};
void PrintTo(const SeriesCase& c, std::ostream* out) { *out << c.name; }

std::vector<SeriesCase> Cases() {
  return {
      {"triple",
       testing::Math(LawType::kTripleFrictionPendulum,
                     {1000, 2100, 280, 280, 2100, 0.06, 0.02, 0.02, 0.10, 400, 50, 50, 400, 0.5}),
       800},
      {"triple_unequal",
       testing::Math(LawType::kTripleFrictionPendulum,
                     {1200, 1800, 300, 250, 2400, 0.05, 0.01, 0.03, 0.09, 250, 60, 40, 350, 1.0}),
       700},
      {"double",
       testing::Math(LawType::kDoubleFrictionPendulum, {800, 2000, 1500, 0.04, 0.07, 300, 250, 1}),
       500},
  };
}

// A plan law with its whole state (PlanStateSlots PlanLawStates).
class DrivenPlanLaw {
 public:
  explicit DrivenPlanLaw(PlanLawKernel kernel)
      : kernel_(std::move(kernel)), committed_(PlanStateSlots(kernel_)) {}
  struct Step {
    std::vector<PlanLawState> state;
    PlanLawResponse response;
  };
  Step Trial(Vec2 u) const { return TrialFrom(committed_, u); }
  Step TrialFrom(const std::vector<PlanLawState>& from, Vec2 u) const {
    Step step{std::vector<PlanLawState>(from.size()), {}};
    UpdatePlanLaw(kernel_, from[0], std::span(from).subspan(1), {u, {}, 0.0}, &step.state[0],
                  std::span(step.state).subspan(1), &step.response);
    return step;
  }
  Step MoveTo(Vec2 u) {
    Step step = Trial(u);
    committed_ = step.state;
    return step;
  }
  const std::vector<PlanLawState>& committed() const { return committed_; }
  void set_committed(std::vector<PlanLawState> s) { committed_ = std::move(s); }
  const PlanSeriesArrangement& law() const { return std::get<PlanSeriesArrangement>(kernel_); }
  double StoredEnergy() const {
    return PlanStoredEnergy(kernel_, committed_[0], std::span(committed_).subspan(1));
  }

 private:
  PlanLawKernel kernel_;
  std::vector<PlanLawState> committed_;
};

std::vector<double> LinePath(double scale) {
  const std::vector<double> turns = {0.0,          scale,       -scale,       0.6 * scale,
                                     -0.3 * scale, 1.2 * scale, -1.2 * scale, 0.1 * scale};
  std::vector<double> path;
  for (std::size_t i = 0; i + 1 < turns.size(); ++i) {
    const int n = static_cast<int>(std::ceil(std::abs(turns[i + 1] - turns[i]) / scale * 61));
    for (int k = 1; k <= n; ++k) path.push_back(turns[i] + (turns[i + 1] - turns[i]) * k / n);
  }
  return path;
}

void ExpectClose(double plan, double line, double reference, const std::string& what) {
  EXPECT_NEAR(plan, line, 1e-11 * std::max({std::abs(plan), std::abs(line), reference})) << what;
}

class PlanSeries : public ::testing::TestWithParam<SeriesCase> {};

TEST_P(PlanSeries, ReducesToItsOneDirectionLawAlongAnyLine) {
  const SeriesCase& c = GetParam();
  for (const double degrees : {0.0, 90.0, 30.0, 135.0, 251.3}) {
    const Vec2 d = degrees == 0.0 ? Vec2{1.0, 0.0}
                   : degrees == 90.0
                       ? Vec2{0.0, 1.0}
                       : Vec2{std::cos(degrees * kPi / 180), std::sin(degrees * kPi / 180)};
    const Vec2 across = Perpendicular(d);
    testing::DrivenLaw line(c.parameters.Kernel());
    DrivenPlanLaw plan(CoupledKernel(c.parameters));
    const SeriesArrangement& series = plan.law().law;
    double force_scale = 1.0;
    int tangents = 0;
    for (const double u : LinePath(c.scale)) {
      const std::vector<LawState> line_from = line.committed();
      const testing::BlockStep one = line.MoveTo(u);
      const DrivenPlanLaw::Step two = plan.MoveTo(u * d);
      force_scale = std::max(force_scale, std::abs(one.response.force));
      const std::string at =
          c.name + " at " + std::to_string(degrees) + " deg, u = " + std::to_string(u) + ": ";
      ExpectClose(Dot(two.response.force, d), one.response.force, force_scale, at + "force");
      ExpectClose(Dot(two.response.force, across), 0.0, force_scale, at + "force across");
      // Away from a breakpoint (where round-off picks the side) the tangents agree.
      const double h = 1e-7 * c.scale;
      const double ahead = line.TrialFrom(line_from, u + h).response.force;
      const double behind = line.TrialFrom(line_from, u - h).response.force;
      if (std::abs((ahead - one.response.force) - (one.response.force - behind)) <
          1e-6 * std::abs(ahead - behind)) {
        const Mat2& k = two.response.stiffness;
        ExpectClose(Dot(d, k * d), one.response.stiffness, one.response.stiffness, at + "tangent");
        ExpectClose(Dot(across, k * d), 0.0, one.response.stiffness, at + "coupling");
        ++tangents;
      }
      ExpectClose(Dissipated(two.state[0]), one.main().dissipated, force_scale * c.scale,
                  at + "dissipated");
      ExpectClose(Dot(Slider(two.state[0]), d), one.main().slider, c.scale, at + "slider");
      for (int k = 1; k <= series.count; ++k) {
        const Vec2 z{two.state[k].x.slider, two.state[k].y.slider};
        ExpectClose(Dot(z, d), one.state[k].slider, c.scale, at + "element");
        ExpectClose(Dot(z, across), 0.0, c.scale, at + "element across");
        EXPECT_EQ(two.state[k].y.slip != 0,
                  StopEngaged(series, std::span(one.state).subspan(1), k - 1))
            << at << "element " << k << " at its stop";
      }
      ExpectClose(plan.StoredEnergy(), line.StoredEnergy(), force_scale * c.scale,
                  at + "stored energy");
      if (series.count == 4) {  // the triple pendulum's regime and capacity used, as in 1-D
        const auto line_elements = std::span<const LawState>(one.state).subspan(1);
        const auto plan_elements = std::span<const PlanLawState>(two.state).subspan(1);
        EXPECT_EQ(TriplePendulumRegime(series, plan_elements),
                  TriplePendulumRegime(series, line_elements))
            << at;
        const auto used_line = TriplePendulumCapacityUsed(series, line_elements);
        const auto used_plan = TriplePendulumCapacityUsed(series, plan_elements);
        for (int i = 0; i < 4; ++i) EXPECT_NEAR(used_plan[i], used_line[i], 1e-12) << at;
      }
    }
    EXPECT_GT(tangents, 300) << c.name;
  }
}

// The Lissajous path of the other plan tests, large enough to reach the rings.
std::vector<Vec2> CurvedPath(double scale, int steps) {
  std::vector<Vec2> path;
  for (int k = 0; k <= steps; ++k) {
    path.push_back(testing::Lissajous(scale, testing::kLissajousDuration * k / steps).u);
  }
  return path;
}

TEST_P(PlanSeries, TangentIsTheDerivativeOfTheUpdateOnCurvedPaths) {
  const SeriesCase& c = GetParam();
  DrivenPlanLaw law(CoupledKernel(c.parameters));
  const SeriesArrangement& series = law.law().law;
  const double h = 1e-7 * c.scale;
  int checked = 0, on_rings = 0;
  for (const Vec2 u : CurvedPath(c.scale, 1500)) {
    const DrivenPlanLaw::Step at = law.Trial(u);
    Mat2 central;
    bool smooth = true;
    double size = 1.0;
    for (const int axis : {0, 1}) {
      const Vec2 e = axis == 0 ? Vec2{h, 0.0} : Vec2{0.0, h};
      const Vec2 ahead = law.Trial(u + e).response.force, behind = law.Trial(u - e).response.force;
      const Vec2 right = (ahead - at.response.force) / h, left = (at.response.force - behind) / h;
      size = std::max({size, Norm(right), Norm(left)});
      smooth = smooth && Norm(right - left) < 1e-5 * size;
      const Vec2 column = 0.5 * (left + right);
      (axis == 0 ? central.xx : central.xy) = column.x;
      (axis == 0 ? central.yx : central.yy) = column.y;
    }
    if (smooth) {
      const Mat2& k = at.response.stiffness;
      const std::string where =
          c.name + " at u = (" + std::to_string(u.x) + ", " + std::to_string(u.y) + ")";
      EXPECT_NEAR(k.xx, central.xx, 1e-5 * size) << where;
      EXPECT_NEAR(k.xy, central.xy, 1e-5 * size) << where;
      EXPECT_NEAR(k.yx, central.yx, 1e-5 * size) << where;
      EXPECT_NEAR(k.yy, central.yy, 1e-5 * size) << where;
      ++checked;
      bool ring = false;
      for (int k = 1; k <= series.count; ++k) {
        ring = ring || (at.state[k].y.slip != 0 && at.state[k].x.slip != 0);
      }
      on_rings += ring;
    }
    law.set_committed(at.state);
  }
  EXPECT_GT(checked, 600) << c.name;
  EXPECT_GT(on_rings, 100) << c.name << ": too few checks while an element slides round its ring";
}

TEST_P(PlanSeries, ElementsStayInTheirRingsAndFrictionCirclesAndDissipateTheirWork) {
  const SeriesCase& c = GetParam();
  DrivenPlanLaw law(CoupledKernel(c.parameters));
  const SeriesArrangement& series = law.law().law;
  double work = 0.0, work_scale = 0.0;
  Vec2 force, u_before;
  for (const Vec2 u : CurvedPath(c.scale, 6000)) {
    const std::vector<PlanLawState> from = law.committed();
    const DrivenPlanLaw::Step step = law.MoveTo(u);
    const Vec2 f = step.response.force;
    work += 0.5 * Dot(force + f, u - u_before);
    work_scale += std::abs(0.5 * Dot(force + f, u - u_before));
    force = f;
    u_before = u;
    double element_work = 0.0;
    for (int k = 0; k < series.count; ++k) {
      const SeriesElement& e = series.elements[k];
      const Vec2 z{step.state[k + 1].x.slider, step.state[k + 1].y.slider};
      const Vec2 z_n{from[k + 1].x.slider, from[k + 1].y.slider};
      const Vec2 moved = z - z_n;
      const double tolerance = 1e-9 * (e.strength + Norm(f));
      EXPECT_LE(Norm(z), e.stop * (1 + 1e-14));
      // The force less the pendulum's, less the ring's reaction along z: the friction.
      Vec2 friction = f - e.stiffness * z;
      if (step.state[k + 1].y.slip != 0)
        friction = friction - Dot(friction, z / Norm(z)) * (z / Norm(z));
      EXPECT_LE(Norm(friction), e.strength + tolerance) << c.name << " element " << k;
      if (Norm(moved) > 1e-9 * c.scale) {  // along the chord it moved (backward Euler)
        const Vec2 along = moved / Norm(moved);
        if (step.state[k + 1].y.slip == 0) {
          EXPECT_NEAR(Dot(friction, along), e.strength, tolerance) << c.name << " element " << k;
        }
      }
      element_work += e.strength * Norm(moved);
    }
    EXPECT_NEAR(Dissipated(step.state[0]) - Dissipated(from[0]), element_work,
                1e-9 * (1 + element_work));
  }
  // Work = stored + dissipated, to the backward Euler's first order on a curved path.
  const double balance = law.StoredEnergy() + Dissipated(law.committed()[0]);
  EXPECT_NEAR(work, balance, 2e-3 * work_scale) << c.name;
}

// The update is the one solved by iteration: from states along a curved path, trials at every
// distance (round-off to twice the path's size) and direction converge, with every element within
// its ring.
TEST_P(PlanSeries, ConvergesFromAnyStateToAnyTrial) {
  const SeriesCase& c = GetParam();
  DrivenPlanLaw law(CoupledKernel(c.parameters));
  const SeriesArrangement& series = law.law().law;
  const std::vector<Vec2> path = CurvedPath(c.scale, 400);
  int tried = 0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    law.MoveTo(path[k]);
    if (k % 40 != 0) continue;
    const Vec2 from = Displacement(law.committed()[0]);
    for (const double distance : {1e-10, 1e-6, 1e-3, 0.1, 1.0, 2.0}) {
      for (int a = 0; a < 16; ++a) {
        const double angle = 2 * kPi * (a + 0.37) / 16;
        const DrivenPlanLaw::Step trial =
            law.Trial(from + (distance * c.scale) * Vec2{std::cos(angle), std::sin(angle)});
        ASSERT_TRUE(std::isfinite(trial.response.force.x) && std::isfinite(trial.response.force.y))
            << c.name << " from step " << k << ", distance " << distance << ", angle " << angle;
        for (int e = 0; e < series.count; ++e) {
          const Vec2 z{trial.state[e + 1].x.slider, trial.state[e + 1].y.slider};
          EXPECT_LE(Norm(z), series.elements[e].stop * (1 + 1e-14));
        }
        ++tried;
      }
    }
  }
  EXPECT_EQ(tried, 11 * 6 * 16);
}

INSTANTIATE_TEST_SUITE_P(MultiplePendulums, PlanSeries, ::testing::ValuesIn(Cases()),
                         [](const auto& info) { return info.param.name; });

// ---- Circular orbits against the closed form of steady circular sliding (header). ----
struct SteadyOrbit {
  double force, dissipation;  // |F| and energy per revolution
};
double OrbitRadius(const SeriesArrangement& s, double force, double* dissipation) {
  double along = force / s.ke, across = 0.0, dissipated = 0.0;
  for (int k = 0; k < s.count; ++k) {
    const SeriesElement& e = s.elements[k];
    const double sine = e.strength / force, cosine = std::sqrt(1 - sine * sine);
    const double r =
        std::min(e.stop, std::sqrt(force * force - e.strength * e.strength) / e.stiffness);
    along += r * cosine;
    across += r * sine;
    dissipated += 2 * kPi * e.strength * r;
  }
  if (dissipation) *dissipation = dissipated;
  return std::hypot(along, across);
}
SteadyOrbit ClosedFormOrbit(const SeriesArrangement& s, double radius) {
  double low = 0.0;
  for (int k = 0; k < s.count; ++k) low = std::max(low, s.elements[k].strength);
  double high = 2 * low;
  while (OrbitRadius(s, high, nullptr) < radius) high *= 2;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    (OrbitRadius(s, mid, nullptr) < radius ? low : high) = mid;
  }
  SteadyOrbit orbit{0.5 * (low + high), 0.0};
  OrbitRadius(s, orbit.force, &orbit.dissipation);
  return orbit;
}

// From rest out to (A, 0), then revolutions of N steps; the last revolution's |F| (mean) and
// dissipation.
SteadyOrbit DriveOnCircle(const LawParameters& parameters, double radius, int steps) {
  DrivenPlanLaw law(CoupledKernel(parameters));
  for (int k = 1; k <= 100; ++k) law.MoveTo({radius * k / 100, 0.0});
  SteadyOrbit measured{};
  for (int revolution = 0; revolution < 3; ++revolution) {
    const double before = Dissipated(law.committed()[0]);
    double force = 0.0;
    for (int k = 1; k <= steps; ++k) {
      const double theta = 2 * kPi * k / steps;
      force += Norm(law.MoveTo(radius * Vec2{std::cos(theta), std::sin(theta)}).response.force);
    }
    measured = {force / steps, Dissipated(law.committed()[0]) - before};
  }
  return measured;
}

TEST(PlanSeriesOrbit, TriplePendulumOnACircleBeyondAllRegimesAndInsideThem) {
  const LawParameters triple = Cases()[0].parameters;
  const SeriesArrangement series = std::get<SeriesArrangement>(triple.Kernel());
  // Beyond all regimes: every element round its ring, 2 pi sum f d a revolution whatever A.
  double beyond = 0.0;
  for (int k = 0; k < series.count; ++k) {
    beyond += 2 * kPi * series.elements[k].strength * series.elements[k].stop;
  }
  // Inside every ring; the outer elements round theirs, the inner inside; all round theirs.
  for (const double radius : {300.0, 600.0, 850.0, 1300.0}) {
    const SteadyOrbit exact = ClosedFormOrbit(series, radius);
    const SteadyOrbit coarse = DriveOnCircle(triple, radius, 2000);
    const SteadyOrbit fine = DriveOnCircle(triple, radius, 8000);
    const std::string where = "A = " + std::to_string(radius);
    // First order in the steps (backward Euler): four times the steps, a quarter of the error.
    const double coarse_error = std::abs(coarse.dissipation / exact.dissipation - 1);
    const double fine_error = std::abs(fine.dissipation / exact.dissipation - 1);
    EXPECT_LT(fine_error, 2e-3) << where;
    EXPECT_LT(fine_error, 0.4 * coarse_error + 1e-6) << where;
    EXPECT_NEAR(fine.force / exact.force, 1.0, 2e-3) << where;
    if (radius > 1000) {
      EXPECT_NEAR(exact.dissipation, beyond, 1e-9 * beyond) << where;
    }
  }
}

TEST(PlanSeriesAssembly, ATriplePendulumBesideOtherLawsKeepsItsStatesAfterTheirs) {
  const LawParameters triple = Cases()[0].parameters;
  const LawParameters bhm2 = testing::Math(LawType::kBhm2, {10, 1, 1});
  const PlanAssembly assembly({{"tfp", triple, std::nullopt}, {"bhm2", bhm2, std::nullopt}});
  ASSERT_EQ(assembly.size(), 2u);
  ASSERT_EQ(assembly.state_size(), 2u + 4u);
  EXPECT_EQ(assembly.ElementStatesOffset(0), 2u);
  std::vector<PlanLawState> committed(assembly.state_size()), trial(assembly.state_size());
  std::vector<PlanLawResponse> responses(assembly.size());
  DrivenPlanLaw alone(CoupledKernel(triple));
  for (const Vec2 u : CurvedPath(700, 300)) {
    const PlanResponse total = assembly.Update(committed, {u, {}, 0.0}, trial, responses);
    const DrivenPlanLaw::Step one = alone.MoveTo(u);
    EXPECT_EQ(responses[0].force, one.response.force);
    EXPECT_EQ(total.force, responses[0].force + responses[1].force);
    for (int k = 1; k <= 4; ++k) EXPECT_EQ(trial[1 + k].x.slider, one.state[k].x.slider);
    std::swap(committed, trial);
  }
  EXPECT_EQ(assembly.DissipatedEnergy(committed),
            Dissipated(alone.committed()[0]) + Dissipated(committed[1]));
  EXPECT_NEAR(assembly.StoredEnergy(committed),
              alone.StoredEnergy() + PlanStoredEnergy(CoupledKernel(bhm2), committed[1]), 1e-9);
  // A plan structure's flat storage (LawState pairs) gives the same update.
  const PlanLawKernel kernel = CoupledKernel(triple);
  const PlanSeriesArrangement& plan = std::get<PlanSeriesArrangement>(kernel);
  std::vector<LawState> flat(2 * 5), flat_trial(2 * 5);
  DrivenPlanLaw paired(CoupledKernel(triple));
  for (const Vec2 u : CurvedPath(700, 200)) {
    PlanLawResponse response;
    plan.UpdateFlat({flat[0], flat[1]}, std::span(flat).subspan(2), {u, {}, 0.0},
                    {flat_trial[0], flat_trial[1]}, std::span(flat_trial).subspan(2), &response);
    const DrivenPlanLaw::Step step = paired.MoveTo(u);
    EXPECT_EQ(response.force, step.response.force);
    for (int k = 1; k <= 4; ++k) EXPECT_EQ(flat_trial[2 * k + 1].slider, step.state[k].y.slider);
    std::swap(flat, flat_trial);
  }
  EXPECT_EQ(plan.StoredEnergyFlat({flat[0], flat[1]}, std::span(flat).subspan(2)),
            paired.StoredEnergy());
  // An uncoupled pair cannot hold a law of several states.
  EXPECT_THROW(PlanAssembly({{"pair", triple, triple}}), std::invalid_argument);
}

}  // namespace
}  // namespace isolab::hysteresis
