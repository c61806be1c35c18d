// Chopra's El Centro examples on the bundled record: Case C, linear SDOF peaks (Sec. 6.4, the
// book's values recomputed at the record's samples), and Case E, the five-story shear frame
// against an independent modal solution.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "isolab/hysteresis/law_parameters.h"
#include "isolab/integrators/newmark.h"
#include "isolab/io/record.h"
#include "isolab/structure/shear_building.h"
#include "reference_data.h"

namespace isolab::integrators {
namespace {

using hysteresis::LawType;
using hysteresis::ParallelAssembly;

constexpr double kGravity = 386.4;  // in/s^2, as in Chopra

ParallelAssembly Linear(double k) { return hysteresis::SingleLaw(LawType::kLinearSpring, {k}); }

// Chopra's record: El Centro NS 1940 in g at 0.02 s, with a(0) = 0 at t = 0.
Excitation ElCentro() {
  const io::Record record = io::ReadRecord(testing::ElCentroPath().string());
  Excitation excitation = Excitation::Uniform({});
  excitation.ground[0].acceleration.dt = record.dt;
  for (const double a : record.values)
    excitation.ground[0].acceleration.values.push_back(a * kGravity);
  return excitation;
}

TEST(ChopraCaseC, LinearSdofPeakDisplacements) {
  const Excitation excitation = ElCentro();
  struct Case {
    double period, zeta, peak;  // s, -, in (recomputed peak of 0.02 s samples)
  };
  for (const Case& c : {Case{0.5, 0.02, 2.676}, Case{1.0, 0.02, 5.971}, Case{2.0, 0.02, 7.471},
                        Case{2.0, 0.0, 9.919}, Case{2.0, 0.05, 5.375}}) {
    const double m = 1.0, w = 2 * std::numbers::pi / c.period;
    const auto sdof = structure::BuildSdof(m, 2 * c.zeta * w * m, Linear(w * w * m)).structure;
    ResponseHistory response;
    // dt = 0.005 s, a quarter of the record's step (linear between samples), output at 0.02 s
    // samples as the reference takes its peak.
    const int steps = static_cast<int>(excitation.duration() / 0.005);
    const RunSummary summary = RunNewmark(sdof, excitation, {0.005, steps}, {}, &response);
    ASSERT_TRUE(summary.ok()) << summary.message;
    double peak = 0.0;
    for (int k = 0; k <= steps; k += 4)
      peak = std::max(peak, std::abs(response.displacement(k, 0)));
    EXPECT_NEAR(peak / c.peak, 1.0, 0.005) << "Tn = " << c.period << ", zeta = " << c.zeta;
    std::printf("Case C Tn = %.1f s, zeta = %.2f: D = %.4f in (reference %.3f)\n", c.period, c.zeta,
                peak, c.peak);
  }
}

TEST(ChopraCaseE, FiveStoryFramePeaksMatchTheModalSolution) {
  structure::ShearBuilding building;
  for (int i = 0; i < 5; ++i)
    building.stories.push_back({"story", 100.0 / kGravity, 144.0, Linear(31.54)});
  building.damping.kind = structure::SuperstructureDamping::Kind::kModal;
  building.damping.modal_ratios = {0.05};
  const auto frame = structure::BuildShearBuilding(building).structure;
  const Excitation excitation = ElCentro();
  ResponseHistory response;
  const int steps = static_cast<int>(excitation.duration() / 0.005);
  const RunSummary summary = RunNewmark(frame, excitation, {0.005, steps}, {}, &response);
  ASSERT_TRUE(summary.ok()) << summary.message;
  double roof = 0, base_shear = 0, top_shear = 0;
  for (int k = 0; k <= steps; k += 4) {  // the reference's 0.02 s samples
    roof = std::max(roof, std::abs(response.displacement(k, 4)));
    base_shear = std::max(base_shear, std::abs(response.connection_force(k, 0)));
    top_shear = std::max(top_shear, std::abs(response.connection_force(k, 4)));
  }
  std::printf("Case E: roof %.4f in, base shear %.3f kip, top shear %.3f kip, energy error %.2e\n",
              roof, base_shear, top_shear, summary.energy_balance_error);
  EXPECT_NEAR(roof / 6.857, 1.0, 0.01);
  EXPECT_NEAR(base_shear / 73.09, 1.0, 0.01);
  EXPECT_NEAR(top_shear / 35.24, 1.0, 0.01);
  EXPECT_LT(summary.energy_balance_error, 1e-3);
}

}  // namespace
}  // namespace isolab::integrators
