// The bundled bearing study (models/studies/five_story_bearings.yaml): every variant under every
// bundled record closes its energy balance with Newmark, and IDA agrees with Newmark on the
// lead-rubber (heated) and friction pendulum variants under the 2 s pulse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

#include "doc_table_row.h"
#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/model/study_file.h"
#include "paper_tables.h"

namespace isolab::study {
namespace {

model::StudyFile BearingStudy() {
  return model::LoadStudyFile(ISOLAB_SOURCE_DIR "/models/studies/five_story_bearings.yaml");
}

integrators::ResponseHistory RunVariant(const model::StudyVariant& variant,
                                        const model::StudyRecord& record,
                                        model::AnalysisSection analysis,
                                        integrators::RunSummary* summary, double scale = 0.75) {
  analysis::RunOverrides overrides;
  overrides.records.push_back({.file = record.components[0].file});
  overrides.scale = scale;
  const analysis::Problem problem = analysis::Prepare(variant.model, overrides);
  integrators::ResponseHistory response;
  integrators::HistoryRecorder recorder =
      integrators::RecordHistory(problem.structure, problem.grid, &response);
  integrators::ResponseObserver* const also[] = {&recorder};
  analysis::SolveOptions options;
  options.analysis = analysis;
  *summary = analysis::Solve(options, problem, also).run;
  return response;
}

TEST(BearingStudy, EveryVariantClosesItsEnergyBalanceUnderEveryRecord) {
  const model::StudyFile study = BearingStudy();
  ASSERT_EQ(study.variants.size(), 5u);
  ASSERT_EQ(study.records.size(), 3u);
  for (const model::StudyVariant& variant : study.variants) {
    for (const model::StudyRecord& record : study.records) {
      integrators::RunSummary summary;
      RunVariant(variant, record, variant.model.analysis, &summary);
      ASSERT_TRUE(summary.ok()) << variant.name << " / " << record.name << ": " << summary.message;
      EXPECT_LT(summary.energy_balance_error, 1e-4) << variant.name << " / " << record.name;
    }
  }
}

// docs/bearings.md quotes this test's rows (scripts/doc_tables/test_printout.py).
TEST(BearingStudy, IdaAgreesWithNewmarkOnTheHeatedLeadRubberAndTheFrictionPendulum) {
  const model::StudyFile study = BearingStudy();
  const model::StudyRecord* pulse = nullptr;
  for (const auto& record : study.records) {
    if (record.name == "pulse_tp2") pulse = &record;
  }
  ASSERT_NE(pulse, nullptr);
  const std::pair<std::string, std::string> compared[] = {
      {"lead_rubber", "heated lead-rubber"}, {"friction_pendulum", "friction pendulum"}};
  isolab::testing::PrintTableHeader({"variant", "Newmark peak [mm]", "IDA peak [mm]", "difference",
                                     "energy balance Newmark / IDA"});
  for (const auto& [name, description] : compared) {
    const auto variant = std::find_if(study.variants.begin(), study.variants.end(),
                                      [&](const auto& v) { return v.name == name; });
    ASSERT_NE(variant, study.variants.end()) << name;
    model::AnalysisSection ida = variant->model.analysis;
    ida.integrator = model::AnalysisSection::Integrator::kIda;
    ida.ida.relative_tolerance = 1e-8;
    ida.ida.absolute_tolerance = 1e-8;
    integrators::RunSummary newmark_summary, ida_summary;
    const auto a = RunVariant(*variant, *pulse, variant->model.analysis, &newmark_summary);
    const auto b = RunVariant(*variant, *pulse, ida, &ida_summary);
    ASSERT_TRUE(ida_summary.ok()) << ida_summary.message;
    const double peak_newmark = a.displacement.col(0).cwiseAbs().maxCoeff();
    const double peak_ida = b.displacement.col(0).cwiseAbs().maxCoeff();
    isolab::testing::PrintTableRow(
        {description, isolab::testing::Fixed(peak_newmark, 3), isolab::testing::Fixed(peak_ida, 3),
         isolab::testing::Scientific(std::abs(peak_newmark / peak_ida - 1), 0),
         isolab::testing::Scientific(newmark_summary.energy_balance_error, 1) + " / " +
             isolab::testing::Scientific(ida_summary.energy_balance_error, 1)});
    EXPECT_NEAR(peak_newmark / peak_ida, 1.0, 1e-3);  // measured: 1e-5 and 5e-5
    EXPECT_LT(ida_summary.energy_balance_error, 1e-5);
  }
}

// The diagnosed BNCS isolator's third cycle at +-110 mm, T = 2.5 s, from the closed forms of its
// four components (the parameters of models/bncs/bncs_diagnosed.fitted.yaml, typed in):
//   BHM2 with k1 = 0: W_d = 4 fs (A - uy), force fs while it slips;
//   the degrading BHM2: f = phi(kappa) (fs + k1 u) on a slip branch, phi = 1 - loss (1 -
//     exp(-kappa / slip_scale)); it dissipates phi fs per unit slip plus the stored energy
//     (fs uy + k1 u^2) / 2 that the damage releases, -dphi times it, integrated here over the
//     cycle's three slip branches by Simpson's rule; kappa grows by A - uy on the first loading
//     and by 2 (A - uy) each half cycle after, so the third cycle starts (u = 0, going up, past
//     the yield of the reversal at -A) at kappa = 7 (A - uy) + A - 2 uy;
//   the dashpot: c v, its energy summed by the trapezoidal rule over N = 400 samples a cycle,
//     exactly (N / 2) sin(2 pi / N) c omega A^2 (pi c omega A^2 as N grows);
//   THM1: steady loop energy 4 fs u_ha and force ke (A - u_ha) at A (paper_tables.h), slope k2 on
//     the slip branch beyond u_ha > uc, where it is from 60 degrees of the phase to the peak.
// The peak force is the largest |F| of the samples, where the dashpot's force adds to the others
// just before u = A; it is sought over the last 30 degrees before each peak of the cycle.
struct BncsIsolatorThirdCycle {
  double dissipated = 0.0;
  double peak_force = 0.0;
};

BncsIsolatorThirdCycle ClosedFormThirdCycle(double amplitude, double period, int samples) {
  constexpr double pi = std::numbers::pi;
  const double a = amplitude, omega = 2.0 * pi / period;
  // BHM2 "isolators": k0, k1 = 0, uy.
  const double fs_b = 11.3357623 * 0.933048043, uy_b = 0.933048043;
  // degrading_bhm2 "degrading": k0, k1, uy, loss, slip_scale.
  const double k0_d = 13.0723102, k1_d = 7.71231765, uy_d = 4.14687992, loss = 0.433719046,
               scale = 67.7629623;
  const double fs_d = (k0_d - k1_d) * uy_d;
  // dashpot "viscous": c.
  const double c = 0.194266565;
  // thm1 "late_yield": k0, k1, k2, uy, uyh.
  const double thm1[5] = {0.878908704, 8.78914802e-06, -1.28549475, 13.3043349, 29.4624226};
  const double w_thm1 = testing::Thm1CycleEnergy(thm1, a);
  const double fs_t = thm1[0] * thm1[3];
  const double u_ha = w_thm1 / (4.0 * fs_t);
  const double f_thm1 = thm1[0] * (a - u_ha);

  const auto phi = [&](double kappa) { return 1.0 - loss * (1.0 - std::exp(-kappa / scale)); };
  const auto phi_slope = [&](double kappa) { return -loss / scale * std::exp(-kappa / scale); };
  // A slip branch from kappa0 over `length`, u = u0 + s (kappa - kappa0).
  const auto slip_energy = [&](double kappa0, double u0, double s, double length) {
    const auto rate = [&](double kappa) {
      const double u = u0 + s * (kappa - kappa0);
      return phi(kappa) * fs_d - phi_slope(kappa) * 0.5 * (fs_d * uy_d + k1_d * u * u);
    };
    const int n = 4000;  // even
    const double h = length / n;
    double sum = rate(kappa0) + rate(kappa0 + length);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * rate(kappa0 + i * h);
    return sum * h / 3.0;
  };
  const double kappa_start = 7.0 * (a - uy_d) + a - 2.0 * uy_d;
  const double kappa_top = kappa_start + a;                      // up from 0 to A
  const double kappa_bottom = kappa_top + 2.0 * a - 2.0 * uy_d;  // down from A - 2 uy to -A
  const double w_degrading = slip_energy(kappa_start, 0.0, 1.0, a) +
                             slip_energy(kappa_top, a - 2.0 * uy_d, -1.0, 2.0 * a - 2.0 * uy_d) +
                             slip_energy(kappa_bottom, -a + 2.0 * uy_d, 1.0, a - 2.0 * uy_d);
  const double w_dashpot = 0.5 * samples * std::sin(2.0 * pi / samples) * c * omega * a * a;

  BncsIsolatorThirdCycle cycle;
  cycle.dissipated = 4.0 * fs_b * (a - uy_b) + w_degrading + w_dashpot + w_thm1;
  for (int k = samples / 6; k <= samples / 4; ++k) {
    const double phase = 2.0 * pi * k / samples;
    const double u = a * std::sin(phase), v = a * omega * std::cos(phase);
    // Going up to +A (kappa from kappa_start) and, with the signs turned, down to -A.
    const double up =
        fs_b + phi(kappa_start + u) * (fs_d + k1_d * u) + c * v + f_thm1 + thm1[2] * (u - a);
    const double down = fs_b + phi(kappa_top + (a - 2.0 * uy_d) + u) * (fs_d + k1_d * u) + c * v +
                        f_thm1 + thm1[2] * (u - a);
    cycle.peak_force = std::max({cycle.peak_force, up, down});
  }
  return cycle;
}

// models/studies/bncs_bearings.yaml designs each device for the effective stiffness and the
// energy per cycle of the isolator diagnosed from the BNCS shake-table test, at D = 110 mm and
// T = 2.5 s: the file's K_eff = 3.7815 kN/mm and W_d = 38535 kN mm are the closed forms above,
// the design is right if each variant's steady loop gives them back (the bilinear laws' closed
// forms were solved for them to four digits), and every variant closes its energy balance under
// every record.
TEST(BearingStudy, BncsVariantsMatchTheMeasuredIsolatorAtTheDesignDisplacement) {
  const model::StudyFile study =
      model::LoadStudyFile(ISOLAB_SOURCE_DIR "/models/studies/bncs_bearings.yaml");
  ASSERT_EQ(study.variants.size(), 5u);
  ASSERT_EQ(study.variants[study.reference].name, "measured_diagnosed");
  hysteresis::CyclicProtocol protocol;
  protocol.amplitude = 110.0;
  protocol.period = 2.5;
  protocol.cycles = 3;
  const auto third_cycle = [&](const model::StudyVariant& variant) {
    return hysteresis::RunCyclicTest(variant.model.isolation, protocol).cycles.back();
  };
  const hysteresis::CycleSummary measured = third_cycle(study.variants.front());
  const BncsIsolatorThirdCycle closed_form =
      ClosedFormThirdCycle(protocol.amplitude, protocol.period, protocol.steps_per_cycle);
  EXPECT_NEAR(measured.peak_force, closed_form.peak_force, 1e-9 * closed_form.peak_force);
  EXPECT_NEAR(measured.dissipated, closed_form.dissipated, 1e-9 * closed_form.dissipated);
  // What the file states, to its four and five digits.
  EXPECT_NEAR(closed_form.peak_force / 110.0, 3.7815, 1e-4);
  EXPECT_NEAR(closed_form.dissipated, 38535.0, 1.0);
  for (const model::StudyVariant& variant : study.variants) {
    if (variant.name == "measured_diagnosed" || variant.name == "measured_thm1") continue;
    const hysteresis::CycleSummary designed = third_cycle(variant);
    EXPECT_NEAR(designed.peak_force / measured.peak_force, 1.0, 1e-3) << variant.name;
    EXPECT_NEAR(designed.dissipated / measured.dissipated, 1.0, 2e-3) << variant.name;
    for (const model::StudyRecord& record : study.records) {
      integrators::RunSummary summary;
      RunVariant(variant, record, variant.model.analysis, &summary, study.scales.back());
      ASSERT_TRUE(summary.ok()) << variant.name << " / " << record.name << ": " << summary.message;
      EXPECT_LT(summary.energy_balance_error, 1e-4) << variant.name << " / " << record.name;
    }
  }
}

}  // namespace
}  // namespace isolab::study
