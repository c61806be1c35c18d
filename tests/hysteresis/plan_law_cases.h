// The bidirectional laws the plan tests run, each with the 1-D law it extends: every family
// (series, parallel, springs, dashpot, Bouc-Wen, the bearing presets) in the variants the 1-D
// contract tests use. Shared by the plan law, rate-form and assembly tests.
#pragma once

#include <cmath>
#include <numbers>
#include <ostream>
#include <string>
#include <vector>

#include "isolab/hysteresis/law_parameters.h"
#include "isolab/hysteresis/plan_law_kernel.h"

namespace isolab::hysteresis::testing {

struct PlanLawCase {
  std::string name;
  LawParameters parameters;
  double scale;  // displacement range the paths explore
  LawKernel line() const { return parameters.Kernel(); }
  PlanLawKernel plan() const { return CoupledKernel(parameters); }
};

inline void PrintTo(const PlanLawCase& c, std::ostream* out) { *out << c.name; }

inline LawParameters Math(LawType type, std::vector<double> values) {
  return LawParameters::Make(type, ParameterForm::kMathematical, values);
}

inline std::vector<PlanLawCase> PlanLawCases() {
  constexpr double no = NAN;
  return {
      {"thm1_hard", Math(LawType::kThm1, {1, 0.2, 0.45, 20, 120}), 250},
      {"thm1_soft", Math(LawType::kThm1, {1, 0.2, 0.05, 20, 120}), 250},
      {"thm1_negative_k2", Math(LawType::kThm1, {0.863754, 0.402485, -0.792654, 7.146, 125.542}),
       200},
      {"thm1_spring_limit", Math(LawType::kThm1, {1e6, 0.283532, 0.489882, 0, 64.809}), 150},
      {"thm1_mechanical_form",
       LawParameters::Make(LawType::kThm1, ParameterForm::kMechanical,
                           std::vector<double>{1, 0.25, 9.0 / 11.0, 20, 80}),
       250},
      {"thm2_hard", Math(LawType::kThm2, {1, 0.2, 0.45, 20, 120}), 250},
      {"thm2_soft", Math(LawType::kThm2, {1, 0.2, 0.05, 20, 120}), 250},
      {"thm2_uyh_below_uy", Math(LawType::kThm2, {1, 0.2, 0.45, 20, 10}), 250},
      {"thm2_zero_yield", Math(LawType::kThm2, {1, 0.2, 0.45, 0, 120}), 250},
      {"bhm1", Math(LawType::kBhm1, {1, 0.2, 20}), 250},
      {"bhm2", Math(LawType::kBhm2, {1, 0.2, 20}), 250},
      {"elastoplastic", Math(LawType::kElastoplastic, {3.225241, 0.597}), 10},
      {"trilinear_elastic", Math(LawType::kTrilinearElastic, {0.283532, 0.489882, 64.809}), 150},
      {"linear_spring", Math(LawType::kLinearSpring, {0.7}), 100},
      {"dashpot", Math(LawType::kDashpot, {0.02}), 100},
      {"bouc_wen", Math(LawType::kBoucWen, {1.0, 0.05, 0.5, 0.5, 1.0}), 60},
      {"bouc_wen_nu2", Math(LawType::kBoucWen, {1.0, 0.02, 0.6, 0.4, 2.0}), 60},
      {"bouc_wen_nu1_5", Math(LawType::kBoucWen, {1.0, 0.03, 0.3, 0.7, 1.5}), 60},
      {"friction_pendulum", Math(LawType::kFrictionPendulum, {1000, 2000, 1, 0.05, no, no, no}),
       250},
      {"friction_pendulum_mu_of_v",
       Math(LawType::kFrictionPendulum, {1000, 2000, 2, no, 0.03, 0.09, 0.02}), 250},
      {"lead_rubber", Math(LawType::kLeadRubber, {60, 1, 6, no, no, no, no, no, no, no}), 250},
      {"lead_rubber_heated",
       Math(LawType::kLeadRubber, {60, 1, 6, 100, 200, 1.456e-3, no, no, no, no}), 250},
      {"lead_rubber_conduction",
       Math(LawType::kLeadRubber, {60, 1, 6, 100, 200, 1.456e-3, 0.05, 14.1, 60, no}), 250},
      {"hdr_bearing", Math(LawType::kHdrBearing, {4e-4, 331831, 150, 0.15, 1.5, no}), 250},
  };
}

// A Lissajous figure (3:2) from the origin whose size grows and then shrinks over 6 s: loading
// that is never proportional, both components reversing at different times, sharp turns at the
// figure's tips.
struct PlanPathPoint {
  Vec2 u, v;
};
inline constexpr double kLissajousDuration = 6.0;
inline PlanPathPoint Lissajous(double scale, double t) {
  constexpr double pi = std::numbers::pi;
  const double s = t / kLissajousDuration;
  const double a = scale * (1.3 * std::sin(pi * s) + 0.1 * s);
  const double da = scale * (1.3 * pi * std::cos(pi * s) + 0.1);
  const double p = 2 * pi * 3 * s, q = 2 * pi * 2 * s + 0.5;
  const Vec2 shape{std::sin(p), std::sin(q)};
  const Vec2 shape_rate{2 * pi * 3 * std::cos(p), 2 * pi * 2 * std::cos(q)};
  return {a * shape, (1.0 / kLissajousDuration) * (da * shape + a * shape_rate)};
}

}  // namespace isolab::hysteresis::testing
