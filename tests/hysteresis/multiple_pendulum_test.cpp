// The triple and double friction pendulums (multiple_pendulum.h) against what the papers state:
// the triple pendulum's backbone and unloading branches in each of its five regimes against the
// regime table of Fenz & Constantinou (2008), to round-off; its energy per cycle against the area
// of that closed-form loop at three amplitudes; and everything against an independent
// implementation of the series model, run force-controlled with a plain rule per element, written
// from the paper's modified parameters and not from the law's code. Then its regimes at peaks,
// the capacity used on each surface, the parameter rules, the double pendulum as two single
// pendulums in series, and the mapping from OpenSees' TripleFrictionPendulum.
#include "isolab/hysteresis/multiple_pendulum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/law_parameters.h"
#include "series_law_harness.h"

namespace isolab::hysteresis {
namespace {

using testing::DrivenLaw;

// A standard configuration (Fenz & Constantinou 2008: R1 = R4 >> R2 = R3, mu2 = mu3 < mu1 < mu4),
// kN and mm: effective radii, friction coefficients, actual displacement capacities.
constexpr double kW = 1000.0, kUy = 0.5;
constexpr std::array<double, 4> kR = {2100.0, 280.0, 280.0, 2100.0};
constexpr std::array<double, 4> kMu = {0.06, 0.02, 0.02, 0.10};
constexpr std::array<double, 4> kD = {400.0, 50.0, 50.0, 400.0};
constexpr double kKe = 0.02 * kW / kUy;  // lowest friction reached at u_y

std::vector<double> TripleValues(double w, std::array<double, 4> r, std::array<double, 4> mu,
                                 std::array<double, 4> d, double uy) {
  return {w, r[0], r[1], r[2], r[3], mu[0], mu[1], mu[2], mu[3], d[0], d[1], d[2], d[3], uy};
}
LawParameters Triple() {
  return LawParameters::Make(LawType::kTripleFrictionPendulum, ParameterForm::kMechanical,
                             TripleValues(kW, kR, kMu, kD, kUy));
}
SeriesArrangement SeriesOf(const LawKernel& kernel) { return std::get<SeriesArrangement>(kernel); }

// ---- The closed form: Fenz & Constantinou (2008), Table 1, on first loading. ----
// Each regime begins at a force and slides on two surfaces, whose effective radii add; the
// displacement on the surfaces is the sum over regimes of (force gained) x (radii) / W, the
// bearing's is that plus F / ke. Regime V ends when the inner slider reaches its restrainers, at
// the bearing's capacity d1 + d2 + d3 + d4; beyond, only ke deforms.
struct RegimeRow {
  double force_from;
  double radii;  // R_a + R_b of the two surfaces sliding
};
const double kFdr1 = kW * (kMu[0] + kD[0] / kR[0]);  // surface 1 reaches its restrainer
const double kFdr4 = kW * (kMu[3] + kD[3] / kR[3]);  // surface 4 reaches its restrainer
const double kCapacity = kD[0] + kD[1] + kD[2] + kD[3];
const std::vector<RegimeRow> kRegimes = {
    {kMu[1] * kW, kR[1] + kR[2]},  // I: surfaces 2 and 3
    {kMu[0] * kW, kR[0] + kR[2]},  // II: 1 and 3
    {kMu[3] * kW, kR[0] + kR[3]},  // III: 1 and 4
    {kFdr1, kR[1] + kR[3]},        // IV: 2 and 4
    {kFdr4, kR[1] + kR[2]},        // V: 2 and 3
};

double SlidingDisplacement(double force) {  // force >= 0
  double u = 0.0;
  for (std::size_t r = 0; r < kRegimes.size(); ++r) {
    const double end = r + 1 < kRegimes.size() ? kRegimes[r + 1].force_from : INFINITY;
    if (force > kRegimes[r].force_from) {
      u += (std::min(force, end) - kRegimes[r].force_from) * kRegimes[r].radii / kW;
    }
  }
  return std::min(u, kCapacity);
}
// Where regime V ends (the inner slider at its restrainers).
const double kFend = kFdr4 + (kCapacity - SlidingDisplacement(kFdr4)) * kW / (kR[1] + kR[2]);

double BackboneDisplacement(double force) {
  const double sign = force < 0 ? -1.0 : 1.0;
  return force / kKe + sign * SlidingDisplacement(std::abs(force));
}

// Inverts a continuous, increasing, piecewise-linear f given its breakpoints: exact between them.
template <class F>
double Invert(const F& f, std::vector<double> breaks, double target) {
  std::sort(breaks.begin(), breaks.end());
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    const double a = breaks[i], b = breaks[i + 1], fa = f(a), fb = f(b);
    if (target <= fb || i + 2 == breaks.size()) return a + (target - fa) * (b - a) / (fb - fa);
  }
  return NAN;
}
std::vector<double> BackboneBreaks() {
  std::vector<double> breaks = {0.0, kFend, 2 * kFend};
  for (const RegimeRow& row : kRegimes) breaks.push_back(row.force_from);
  for (std::size_t i = 0, n = breaks.size(); i < n; ++i) breaks.push_back(-breaks[i]);
  return breaks;
}
double BackboneForce(double u) { return Invert(BackboneDisplacement, BackboneBreaks(), u); }

// Unloading from a peak force F_max of first loading (the paper's rules for reversal): every group
// of surfaces that slid resumes, the other way, when the force has fallen by twice its friction
// from where it stopped (from F_max, or from the force that pressed it against its restrainer,
// F_dr); one that never slid starts at -mu W. It slides until its restrainer on the other side,
// at -F_dr. Groups: the inner slider (surfaces 2 and 3 together, mu2 = mu3), surface 1, surface 4;
// each adds its share of the radii of the regime table: R2 + R3, R1 - R2, R4 - R3.
struct Group {
  double mu, restrainer_force, radii;
};
const std::vector<Group> kGroups = {
    {kMu[1], kFend, kR[1] + kR[2]}, {kMu[0], kFdr1, kR[0] - kR[1]}, {kMu[3], kFdr4, kR[3] - kR[2]}};

double UnloadingDisplacement(double peak_force, double drop) {  // drop = F_max - F >= 0
  double u = drop / kKe;
  for (const Group& g : kGroups) {
    const double held = std::min(std::max(peak_force, g.mu * kW), g.restrainer_force);
    const double resume = peak_force - (held - 2 * g.mu * kW);
    const double stop = peak_force + g.restrainer_force;
    u += std::clamp(drop - resume, 0.0, stop - resume) * g.radii / kW;
  }
  return u;
}
double UnloadingForce(double peak_force, double peak_u, double u) {
  std::vector<double> breaks = {0.0, 3 * peak_force + 3 * kFend};
  for (const Group& g : kGroups) {
    const double held = std::min(std::max(peak_force, g.mu * kW), g.restrainer_force);
    breaks.push_back(peak_force - (held - 2 * g.mu * kW));
    breaks.push_back(peak_force + g.restrainer_force);
  }
  const double drop =
      Invert([&](double x) { return UnloadingDisplacement(peak_force, x); }, breaks, peak_u - u);
  return peak_force - drop;
}

// A peak force inside each regime (and beyond V) of first loading.
std::vector<std::pair<PendulumRegime, double>> PeaksInEveryRegime() {
  return {{PendulumRegime::kI, 0.5 * (kMu[1] + kMu[0]) * kW},
          {PendulumRegime::kII, 0.5 * (kMu[0] + kMu[3]) * kW},
          {PendulumRegime::kIII, 0.5 * (kMu[3] * kW + kFdr1)},
          {PendulumRegime::kIV, 0.5 * (kFdr1 + kFdr4)},
          {PendulumRegime::kV, 0.5 * (kFdr4 + kFend)},
          {PendulumRegime::kBeyondV, kFend + 50.0}};
}

TEST(TriplePendulum, RegimeTableIsTheOneTheTestAssumes) {
  // Standard configuration: each regime begins after the one before it.
  for (std::size_t r = 1; r < kRegimes.size(); ++r) {
    EXPECT_GT(kRegimes[r].force_from, kRegimes[r - 1].force_from);
  }
  EXPECT_GT(kFend, kFdr4);
}

TEST(TriplePendulum, BackboneAndUnloadingFollowTheRegimeTableInEveryRegime) {
  for (const auto& [regime, peak_force] : PeaksInEveryRegime()) {
    DrivenLaw law(Triple().Kernel());
    const double peak_u = BackboneDisplacement(peak_force);
    const std::string where = "peak in regime " + std::to_string(static_cast<int>(regime));
    for (int k = 1; k <= 300; ++k) {
      const double u = peak_u * k / 300;
      EXPECT_NEAR(law.MoveTo(u).response.force, BackboneForce(u), 1e-12 * peak_force)
          << where << ", loading at u = " << u;
    }
    EXPECT_NEAR(law.force(), peak_force, 1e-12 * peak_force) << where;
    EXPECT_EQ(TriplePendulumRegime(SeriesOf(law.kernel()), std::span(law.committed()).subspan(1)),
              regime)
        << where;
    // Back to the symmetric peak: every unloading regime on the way.
    for (int k = 1; k <= 600; ++k) {
      const double u = peak_u - 2 * peak_u * k / 600;
      EXPECT_NEAR(law.MoveTo(u).response.force, UnloadingForce(peak_force, peak_u, u),
                  1e-12 * peak_force)
          << where << ", unloading at u = " << u;
    }
    EXPECT_NEAR(law.force(), -peak_force, 1e-12 * peak_force) << where;
  }
}

// ---- The independent implementation: the series model, force-controlled. ----
// Fenz & Constantinou's series model of single pendulums with modified parameters, built from R,
// mu, d as the paper writes them; each element moves only when the force exceeds its friction
// plus its pendulum force, and never past its restrainer. A force step of either sign is exact.
class ForceControlledSeries {
 public:
  ForceControlledSeries() {
    const double r12 = kR[0] - kR[1], r43 = kR[3] - kR[2];
    elements_ = {{kMu[0] * kW, r12, kD[0] * r12 / kR[0]},
                 {kMu[1] * kW, kR[1], kD[1] + kD[0] * kR[1] / kR[0]},
                 {kMu[2] * kW, kR[2], kD[2] + kD[3] * kR[2] / kR[3]},
                 {kMu[3] * kW, r43, kD[3] * r43 / kR[3]}};
  }
  void SetForce(double force) {
    force_ = force;
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      const Element& e = elements_[k];
      const double friction = force - kW * z_[k] / e.radius;
      double z = z_[k];
      if (friction > e.strength) z = std::min(e.capacity, (force - e.strength) * e.radius / kW);
      if (friction < -e.strength) z = std::max(-e.capacity, (force + e.strength) * e.radius / kW);
      dissipated_ += e.strength * std::abs(z - z_[k]);
      z_[k] = z;
    }
  }
  double displacement() const { return force_ / kKe + z_[0] + z_[1] + z_[2] + z_[3]; }
  double dissipated() const { return dissipated_; }

 private:
  struct Element {
    double strength, radius, capacity;
  };
  std::vector<Element> elements_;
  std::array<double, 4> z_{};
  double force_ = 0.0, dissipated_ = 0.0;
};

// Force histories that visit every regime loading and unloading, with partial reversals.
std::vector<double> ForceTurns() {
  return {0.0,      0.05 * kW, 0.01 * kW,  0.18 * kW,   0.1 * kW,   0.27 * kW,  -0.12 * kW,
          0.3 * kW, 0.2 * kW,  kFend + 30, -kFend - 30, -0.02 * kW, -0.29 * kW, 0.0};
}

TEST(TriplePendulum, AgreesWithAnIndependentForceControlledSeriesModel) {
  ForceControlledSeries reference;
  DrivenLaw law(Triple().Kernel());
  const std::vector<double> turns = ForceTurns();
  int checked = 0;
  for (std::size_t i = 0; i + 1 < turns.size(); ++i) {
    for (int k = 1; k <= 400; ++k) {
      const double force = turns[i] + (turns[i + 1] - turns[i]) * k / 400;
      reference.SetForce(force);
      const double u = reference.displacement();
      EXPECT_NEAR(law.MoveTo(u).response.force, force, 1e-11 * kW) << "at F = " << force;
      EXPECT_NEAR(law.committed()[0].dissipated, reference.dissipated(),
                  1e-11 * (1 + reference.dissipated()));
      ++checked;
    }
  }
  EXPECT_EQ(checked, 400 * 13);
}

// ---- Energy per cycle: the area of the closed-form loop. ----
// The steady loop between +-peak_force: the unloading branch from +F_max and, by symmetry, the
// loading branch from -F_max; its area by the shoelace formula over the branches' vertices.
double ClosedFormLoopArea(double peak_force) {
  const double peak_u = BackboneDisplacement(peak_force);
  std::vector<double> drops = {0.0, 2 * peak_force};
  for (const Group& g : kGroups) {
    const double held = std::min(std::max(peak_force, g.mu * kW), g.restrainer_force);
    for (const double drop : {peak_force - (held - 2 * g.mu * kW), peak_force + g.restrainer_force})
      if (drop > 0 && drop < 2 * peak_force) drops.push_back(drop);
  }
  std::sort(drops.begin(), drops.end());
  std::vector<std::pair<double, double>> loop;  // (u, F) counter-clockwise
  for (const double drop : drops) {             // unloading: +peak to -peak
    loop.emplace_back(peak_u - UnloadingDisplacement(peak_force, drop), peak_force - drop);
  }
  const std::size_t half = loop.size();
  for (std::size_t i = 0; i < half; ++i) loop.emplace_back(-loop[i].first, -loop[i].second);
  double area = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto& [u0, f0] = loop[i];
    const auto& [u1, f1] = loop[(i + 1) % loop.size()];
    area += u1 * f0 - u0 * f1;  // clockwise in (u, F): positive work
  }
  return 0.5 * area;
}

TEST(TriplePendulum, EnergyPerCycleIsTheClosedFormLoopAreaAtThreeAmplitudes) {
  // Small (regime I), regimes II-III, regimes IV-V.
  for (const double peak_force : {0.04 * kW, 0.2 * kW, 0.5 * (kFdr4 + kFend)}) {
    const double peak_u = BackboneDisplacement(peak_force);
    DrivenLaw law(Triple().Kernel());
    ForceControlledSeries reference;
    const int steps = 2000;
    double work = 0.0, dissipated_at_cycle = 0.0, reference_at_cycle = 0.0;
    for (int cycle = 0; cycle < 3; ++cycle) {
      work = 0.0;
      dissipated_at_cycle = law.committed()[0].dissipated;
      reference_at_cycle = reference.dissipated();
      for (int k = 1; k <= steps; ++k) {
        const double u = peak_u * std::sin(2 * M_PI * k / steps);
        const double before = law.force(), u_before = law.committed()[0].u;
        law.MoveTo(u);
        work += 0.5 * (before + law.force()) * (u - u_before);
        reference.SetForce(law.force());
      }
    }
    const double closed_form = ClosedFormLoopArea(peak_force);
    const double per_cycle = law.committed()[0].dissipated - dissipated_at_cycle;
    EXPECT_NEAR(per_cycle, closed_form, 1e-12 * closed_form) << "F_max = " << peak_force;
    EXPECT_NEAR(reference.dissipated() - reference_at_cycle, closed_form, 1e-12 * closed_form);
    // The loop's own area, by the trapezoid rule on the steps (exact but near breakpoints).
    EXPECT_NEAR(work, closed_form, 2e-4 * closed_form);
  }
  // The three amplitudes reach the regimes they are meant to.
  EXPECT_LT(0.04 * kW, kMu[0] * kW);
  EXPECT_GT(0.2 * kW, kMu[3] * kW);
  EXPECT_LT(0.2 * kW, kFdr1);
}

TEST(TriplePendulum, OneIncrementToRegimeVEqualsTenThousandSmallOnes) {
  const double target = BackboneDisplacement(0.5 * (kFdr4 + kFend));
  for (const double start : {0.0, -0.3 * target, 0.2 * target}) {
    DrivenLaw one(Triple().Kernel()), many(Triple().Kernel());
    one.MoveTo(start);
    many.MoveTo(start);
    const testing::BlockStep big = one.MoveTo(target);
    testing::BlockStep last;
    for (int k = 1; k <= 10000; ++k) last = many.MoveTo(start + (target - start) * k / 10000.0);
    EXPECT_NEAR(big.response.force, last.response.force, 1e-12 * kW);
    EXPECT_NEAR(big.response.stiffness, last.response.stiffness, 1e-12 * kKe);
    EXPECT_NEAR(big.main().dissipated, last.main().dissipated, 1e-12 * big.main().dissipated);
    for (int k = 1; k <= 4; ++k) {
      EXPECT_NEAR(big.state[k].slider, last.state[k].slider, 1e-12 * target) << "element " << k;
    }
  }
}

TEST(TriplePendulum, RegimeAtEachPeakAndTheCapacityUsed) {
  for (const auto& [regime, peak_force] : PeaksInEveryRegime()) {
    DrivenLaw law(Triple().Kernel());
    const double peak_u = BackboneDisplacement(peak_force);
    for (int k = 1; k <= 50; ++k) law.MoveTo(peak_u * k / 50);
    const SeriesArrangement series = SeriesOf(law.kernel());
    const auto elements = std::span(law.committed()).subspan(1);
    EXPECT_EQ(TriplePendulumRegime(series, elements), regime);
    const std::array<double, 4> used = TriplePendulumCapacityUsed(series, elements);
    const bool outer_1 = regime >= PendulumRegime::kIV, outer_4 = regime >= PendulumRegime::kV;
    const bool inner = regime == PendulumRegime::kBeyondV;
    // At a restrainer: exactly 1, and the stop is engaged; otherwise below 1.
    EXPECT_EQ(used[0] == 1.0, outer_1) << used[0];
    EXPECT_EQ(used[3] == 1.0, outer_4) << used[3];
    EXPECT_EQ(used[1] == 1.0 && used[2] == 1.0, inner) << used[1] << " " << used[2];
    EXPECT_EQ(StopEngaged(series, elements, 0), outer_1);
    EXPECT_EQ(StopEngaged(series, elements, 3), outer_4);
    for (const double fraction : used) EXPECT_LE(fraction, 1.0);
    // Moving back a little: nothing slides, the regime reads sticking, the capacity stays.
    law.MoveTo(peak_u - 0.01);
    if (regime != PendulumRegime::kBeyondV) {
      EXPECT_EQ(TriplePendulumRegime(series, std::span(law.committed()).subspan(1)),
                PendulumRegime::kSticking);
    }
  }
}

TEST(TriplePendulum, SurfaceDisplacementsMoveAsThePaperDescribes) {
  DrivenLaw law(Triple().Kernel());
  const SeriesArrangement series = SeriesOf(law.kernel());
  const auto surfaces = [&] {
    return TriplePendulumSurfaceDisplacements(series, std::span(law.committed()).subspan(1));
  };
  // Regime I: surfaces 2 and 3 alone, (F - mu2 W) R / W each.
  const double f1 = 0.5 * (kMu[1] + kMu[0]) * kW;
  law.MoveTo(BackboneDisplacement(f1));
  std::array<double, 4> u = surfaces();
  EXPECT_NEAR(u[1], (f1 - kMu[1] * kW) * kR[1] / kW, 1e-12 * kD[1]);
  EXPECT_NEAR(u[2], (f1 - kMu[2] * kW) * kR[2] / kW, 1e-12 * kD[2]);
  EXPECT_EQ(u[0], 0.0);
  EXPECT_EQ(u[3], 0.0);
  // Regime II: surface 1 slides, (F - mu1 W) R1 / W; surface 2 stays where regime I left it.
  const double u2_at_start = (kMu[0] - kMu[1]) * kR[1];
  for (const double f : {0.07 * kW, 0.09 * kW}) {
    law.MoveTo(BackboneDisplacement(f));
    u = surfaces();
    EXPECT_NEAR(u[0], (f - kMu[0] * kW) * kR[0] / kW, 1e-12 * kD[0]);
    EXPECT_NEAR(u[1], u2_at_start, 1e-12 * kD[1]);
    EXPECT_NEAR(u[2], (f - kMu[2] * kW) * kR[2] / kW, 1e-12 * kD[2]);
  }
  // The surfaces add up to the displacement on the sliders.
  EXPECT_NEAR(u[0] + u[1] + u[2] + u[3], law.committed()[0].slider, 1e-12 * kCapacity);
}

TEST(TriplePendulum, ParameterRulesNameTheKey) {
  const auto violation = [](std::vector<double> values) {
    try {
      LawParameters::Make(LawType::kTripleFrictionPendulum, ParameterForm::kMechanical, values);
    } catch (const InvalidParameter& error) {
      return error.violation();
    }
    ADD_FAILURE() << "accepted";
    return ParameterViolation{};
  };
  const std::vector<double> good = TripleValues(kW, kR, kMu, kD, kUy);
  auto with = [&](int index, double value) {
    std::vector<double> v = good;
    v[index] = value;
    return v;
  };
  EXPECT_EQ(violation(with(0, 0.0)).key, "w");
  EXPECT_EQ(violation(with(1, 280.0)).key, "r1");  // r1 = r2: element 1 would have R = 0
  EXPECT_NE(violation(with(1, 280.0)).rule.find("r1 - r2"), std::string::npos);
  EXPECT_EQ(violation(with(4, 200.0)).key, "r4");
  EXPECT_EQ(violation(with(6, 0.07)).key, "mu2");  // the inner surface rougher than surface 1
  EXPECT_EQ(violation(with(7, 0.11)).key, "mu3");
  EXPECT_EQ(violation(with(10, -1.0)).key, "d2");
  // The inner slider travels (mu1 - mu2) r2 = 0.04 x 280 = 11.2 mm on surface 2 before surface 1
  // slides: an inner capacity of 5 mm would stop it there, which the series model cannot show.
  const ParameterViolation inner = violation(with(10, 5.0));
  EXPECT_EQ(inner.key, "d2");
  EXPECT_NE(inner.rule.find("(mu1 - mu2) r2 = 11.2"), std::string::npos) << inner.rule;
  EXPECT_EQ(violation(with(11, 22.3)).key, "d3");  // (mu4 - mu3) r3 = 0.08 x 280 = 22.4
  EXPECT_NO_THROW(LawParameters::Make(LawType::kTripleFrictionPendulum, ParameterForm::kMechanical,
                                      with(11, 22.5)));
  EXPECT_EQ(violation(with(13, 0.0)).key, "uy");
  EXPECT_EQ(violation(with(9, NAN)).key, "d1");  // required
  // Allowed: mu2 != mu3, mu4 < mu1 (the mirror), unequal outer surfaces.
  EXPECT_NO_THROW(LawParameters::Make(
      LawType::kTripleFrictionPendulum, ParameterForm::kMechanical,
      TripleValues(kW, {2100, 280, 300, 1800}, {0.10, 0.02, 0.03, 0.06}, {400, 50, 60, 300}, 1)));
  // The same keys in both forms.
  const LawParameters math =
      LawParameters::Make(LawType::kTripleFrictionPendulum, ParameterForm::kMathematical, good);
  EXPECT_EQ(math.Values(ParameterForm::kMechanical), good);
}

// ---- The double pendulum: two single pendulums in series (Fenz & Constantinou 2006). ----
TEST(DoublePendulum, BackboneIsTwoSinglePendulumsInSeries) {
  // R1 = 2000, R2 = 1500, mu1 = 0.04, mu2 = 0.07, d1 = 300, d2 = 250, W = 800, u_y = 1.
  const LawParameters dfp =
      LawParameters::Make(LawType::kDoubleFrictionPendulum, ParameterForm::kMechanical,
                          std::vector<double>{800, 2000, 1500, 0.04, 0.07, 300, 250, 1});
  const double w = 800, ke = 0.04 * w / 1;
  // Sliding on 1 from mu1 W, on both from mu2 W (F = W u / (R1 + R2) + (mu1 R1 + mu2 R2) W /
  // (R1 + R2) on the rigid-plastic part), surface 1 at its restrainer from W (mu1 + d1/R1), then 2
  // alone until its own at W (mu2 + d2/R2).
  const auto sliding = [&](double f) {
    const double u1 = std::clamp((f - 0.04 * w) * 2000 / w, 0.0, 300.0);
    const double u2 = std::clamp((f - 0.07 * w) * 1500 / w, 0.0, 250.0);
    return u1 + u2;
  };
  const std::vector<double> breaks = {
      0.0, 0.04 * w, 0.07 * w, w * (0.04 + 0.15), w * (0.07 + 250.0 / 1500), 1000.0};
  DrivenLaw law(dfp.Kernel());
  for (int k = 1; k <= 700; ++k) {
    const double u = 600.0 * k / 700;
    const double exact = Invert([&](double f) { return f / ke + sliding(f); }, breaks, u);
    EXPECT_NEAR(law.MoveTo(u).response.force, exact, 1e-12 * w) << "u = " << u;
  }
  // A double pendulum has no triple pendulum's regimes.
  const std::vector<LawState> block(3);
  EXPECT_THROW(TriplePendulumRegime(SeriesOf(dfp.Kernel()), std::span(block).subspan(1)),
               std::invalid_argument);
  // Both regimes where both surfaces slide: the combined law of the paper.
  const double f_mid = 0.1 * w, u_mid = f_mid / ke + sliding(f_mid);
  DrivenLaw fresh(dfp.Kernel());
  EXPECT_NEAR(fresh.MoveTo(u_mid).response.force,
              (w * (u_mid - f_mid / ke) + (0.04 * 2000 + 0.07 * 1500) * w) / 3500, 1e-12 * w);
  EXPECT_NEAR(fresh.Trial(u_mid).response.stiffness, 1.0 / (1.0 / ke + 3500 / w), 1e-12);
}

// ---- OpenSees' TripleFrictionPendulum (Dao et al. 2013) mapped to isolab's keys. ----
// OpenSees takes the inner slider's effective radius L1, friction mu1 and capacity d1 for both
// inner surfaces, and the outer surfaces' L2, mu2, d2 (slides first) and L3, mu3, d3; its series
// elements are the inner pair (radius 2 L1, capacity 2 (d1 + L1 d3 / L3)) and the outer ones
// (L2 - L1 with d2 (1 - L1/L2); L3 - L1 with d3 (1 - L1/L3)), and its manual states the bearing's
// capacity 2 d1 + d2 + d3 + L1 d3 / L3 - L1 d2 / L2. isolab: r1 = L2, r2 = r3 = L1, r4 = L3,
// mu1 = mu2_os, mu2 = mu3 = mu1_os, mu4 = mu3_os, d1 = d2_os, d2 = d3 = d1_os, d4 = d3_os.
TEST(TriplePendulum, OpenSeesTripleFrictionPendulumMapsToTheSameSeriesModel) {
  // The values of OpenSees' own TripleFrictionPendulum check (N, m).
  const double l1 = 0.36, l2 = 1.25, l3 = 1.25, mu1 = 0.012, mu2 = 0.052, mu3 = 0.14;
  const double d1 = 0.1, d2 = 0.2, d3 = 0.2, w = 1000.0, uy = 0.001;
  const LawParameters isolab = LawParameters::Make(
      LawType::kTripleFrictionPendulum, ParameterForm::kMechanical,
      TripleValues(w, {l2, l1, l1, l3}, {mu2, mu1, mu1, mu3}, {d2, d1, d1, d3}, uy));
  const SeriesArrangement series = SeriesOf(isolab.Kernel());
  // The inner pair: radius 2 L1, capacity 2 (d1 + L1 d3 / L3), friction mu1 W.
  EXPECT_NEAR(1 / series.elements[1].stiffness + 1 / series.elements[2].stiffness, 2 * l1 / w,
              1e-15);
  EXPECT_NEAR(series.elements[1].stop + series.elements[2].stop, 2 * (d1 + l1 * d3 / l3), 1e-15);
  EXPECT_EQ(series.elements[1].strength, mu1 * w);
  // The outer elements.
  EXPECT_NEAR(1 / series.elements[0].stiffness, (l2 - l1) / w, 1e-15);
  EXPECT_NEAR(series.elements[0].stop, d2 * (1 - l1 / l2), 1e-15);
  EXPECT_EQ(series.elements[0].strength, mu2 * w);
  EXPECT_NEAR(1 / series.elements[3].stiffness, (l3 - l1) / w, 1e-15);
  EXPECT_NEAR(series.elements[3].stop, d3 * (1 - l1 / l3), 1e-15);
  EXPECT_EQ(series.elements[3].strength, mu3 * w);
  // The manual's capacity: the sliding displacement once every restrainer is engaged.
  DrivenLaw law(isolab.Kernel());
  const double capacity = 2 * d1 + d2 + d3 + l1 * d3 / l3 - l1 * d2 / l2;
  law.MoveTo(capacity + 0.05);
  EXPECT_NEAR(law.committed()[0].slider, capacity, 1e-15);
  EXPECT_EQ(TriplePendulumRegime(series, std::span(law.committed()).subspan(1)),
            PendulumRegime::kBeyondV);
  // Beyond, only the pre-slide spring deforms: ke = min(mu) W / u_y.
  EXPECT_NEAR(law.Trial(capacity + 0.06).response.stiffness, mu1 * w / uy, 1e-9 * mu1 * w / uy);
}

}  // namespace
}  // namespace isolab::hysteresis
