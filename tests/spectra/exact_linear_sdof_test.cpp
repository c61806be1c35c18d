// The piecewise-exact recurrence (Chopra Sec. 5.2) against closed forms: it must reproduce the
// step and ramp responses of a damped oscillator to round-off whatever the step, and the
// harmonic response to the accuracy of the sampled (linearly interpolated) load; and against the
// project's Newmark integrator at a fine step.
#include "isolab/spectra/exact_linear_sdof.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/law_parameters.h"
#include "isolab/integrators/newmark.h"
#include "isolab/io/record.h"
#include "isolab/structure/shear_building.h"

namespace isolab::spectra {
namespace {

using integrators::SampledHistory;
constexpr double kPi = std::numbers::pi;

SampledHistory Sampled(double dt, int samples, double (*a)(double)) {
  SampledHistory history{dt, {}};
  for (int k = 0; k < samples; ++k) history.values.push_back(a(k * dt));
  return history;
}

// u(t) under p = -a_g = 1 from t = 0 (Chopra Eq. 4.3.3, per unit mass).
double StepResponse(double omega, double zeta, double t) {
  const double root = std::sqrt(1 - zeta * zeta), wd = omega * root;
  return (1 - std::exp(-zeta * omega * t) * (std::cos(wd * t) + zeta / root * std::sin(wd * t))) /
         (omega * omega);
}

// u(t) under p = -a_g = t (the particular solution t - 2 zeta / w and the free vibration that
// starts it from rest).
double RampResponse(double omega, double zeta, double t) {
  const double wd = omega * std::sqrt(1 - zeta * zeta);
  return (t - 2 * zeta / omega +
          std::exp(-zeta * omega * t) * (2 * zeta / omega * std::cos(wd * t) -
                                         (1 - 2 * zeta * zeta) / wd * std::sin(wd * t))) /
         (omega * omega);
}

TEST(ExactLinearSdof, StepAndRampResponsesAreExactForAnyStep) {
  for (const double zeta : {0.0, 0.02, 0.2, 0.7}) {
    for (const double dt_over_t : {0.01, 0.13, 0.6}) {  // up to a step longer than half a period
      const double period = 0.8, omega = 2 * kPi / period, dt = dt_over_t * period;
      const int samples = static_cast<int>(6 * period / dt) + 2;
      const auto step =
          ExactDeformationHistory(Sampled(dt, samples, [](double) { return -1.0; }), period, zeta);
      const auto ramp =
          ExactDeformationHistory(Sampled(dt, samples, [](double t) { return -t; }), period, zeta);
      ASSERT_EQ(step.size(), std::size_t(samples));
      for (int k = 0; k < samples; ++k) {
        EXPECT_NEAR(step[k], StepResponse(omega, zeta, k * dt), 1e-12 / (omega * omega))
            << "zeta " << zeta << " dt/T " << dt_over_t << " k " << k;
        EXPECT_NEAR(ramp[k], RampResponse(omega, zeta, k * dt), 1e-12 * samples * dt)
            << "zeta " << zeta << " dt/T " << dt_over_t << " k " << k;
      }
    }
  }
}

TEST(ExactLinearSdof, SubstepsVisitTheSameExactSolution) {
  // Sub-steps interpolate the load linearly, so the record's samples are unchanged by them.
  const double period = 0.3, zeta = 0.05;
  const SampledHistory record = Sampled(0.02, 400, [](double t) { return std::sin(7 * t * t); });
  const auto plain = ExactDeformationHistory(record, period, zeta, 1);
  const auto fine = ExactDeformationHistory(record, period, zeta, 7);
  ASSERT_EQ(fine.size(), (plain.size() - 1) * 7 + 1);
  for (std::size_t k = 0; k < plain.size(); ++k) EXPECT_NEAR(fine[7 * k], plain[k], 1e-13);
}

TEST(ExactLinearSdof, HarmonicResponseMatchesChopraClosedForm) {
  // p = -a_g = sin(W t) from rest (Chopra Eq. 3.2.2-3.2.4): steady state plus the transient
  // that starts it from rest. The record samples the sine at W dt = 2 pi / 2000, so the only
  // error is the chord of the interpolated load, (W dt)^2 / 8 = 1.2e-6 relative.
  const double period = 1.0, zeta = 0.05, omega = 2 * kPi / period;
  const double w_force = 0.8 * omega, beta = w_force / omega;
  const double dt = 2 * kPi / w_force / 2000;
  SampledHistory record{dt, {}};
  for (int k = 0; k <= 40000; ++k) record.values.push_back(-std::sin(w_force * k * dt));
  const auto u = ExactDeformationHistory(record, period, zeta);

  const double denominator = std::pow(1 - beta * beta, 2) + std::pow(2 * zeta * beta, 2);
  const double c = (1 - beta * beta) / denominator / (omega * omega);
  const double d = -2 * zeta * beta / denominator / (omega * omega);
  const double wd = omega * std::sqrt(1 - zeta * zeta);
  const double a = -d, b = (zeta * omega * a - w_force * c) / wd;
  double worst = 0.0, closed_form_peak = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) {
    const double t = k * dt;
    const double exact =
        std::exp(-zeta * omega * t) * (a * std::cos(wd * t) + b * std::sin(wd * t)) +
        c * std::sin(w_force * t) + d * std::cos(w_force * t);
    worst = std::max(worst, std::abs(u[k] - exact));
    closed_form_peak = std::max(closed_form_peak, std::abs(exact));
  }
  const double amplitude = std::hypot(c, d);
  EXPECT_LT(worst / amplitude, 5e-6);
  EXPECT_NEAR(ExactPeakDeformation(record, period, zeta).value, closed_form_peak, 5e-6 * amplitude);
}

TEST(ExactLinearSdof, SubstepsFollowPointsPerPeriod) {
  EXPECT_EQ(SubstepsPerSample(0.02, 0.4, 20), 1);  // exactly 20 points: none
  EXPECT_EQ(SubstepsPerSample(0.02, 0.01, 1), 2);  // a period shorter than the record's step
  EXPECT_EQ(SubstepsPerSample(0.02, 0.5, 20), 1);
  EXPECT_EQ(SubstepsPerSample(0.02, 0.05, 20), 8);
  EXPECT_EQ(SubstepsPerSample(0.02, 0.3, 20), 2);
}

TEST(ExactLinearSdof, RejectsOutOfRangeOscillators) {
  const SampledHistory record{0.01, {0.0, 1.0, 0.0}};
  EXPECT_THROW(ExactPeakDeformation(record, 0.0, 0.05), InvalidParameter);
  EXPECT_THROW(ExactPeakDeformation(record, 1.0, -0.01), InvalidParameter);
  EXPECT_THROW(ExactPeakDeformation(record, 1.0, 1.0), InvalidParameter);
  EXPECT_THROW(ExactPeakDeformation(record, 1.0, 0.05, 0), InvalidParameter);
}

// The recurrence and Newmark (average acceleration) share no code; on a bundled record they must
// agree to Newmark's period error. At h <= T/2000 that is (pi^2/12)(h/T)^2 = 2e-7 a cycle, under
// 2e-4 of phase (so of peak) over the record's 150 cycles of the shortest period.
TEST(ExactLinearSdof, AgreesWithNewmarkAtAFineStep) {
  const io::Record record =
      io::ReadRecord(std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/fwn_firm_seed1.at2");
  integrators::Excitation excitation = integrators::Excitation::Uniform({});
  excitation.ground[0].acceleration.dt = record.dt;
  for (const double a : record.values)
    excitation.ground[0].acceleration.values.push_back(a * 9.80665);
  for (const double period : {0.2, 0.5, 1.0, 3.0}) {
    const int substeps = SubstepsPerSample(record.dt, period, 2000);
    const double h = record.dt / substeps;
    const int steps = static_cast<int>(record.values.size() - 1) * substeps;
    for (const double zeta : {0.0, 0.05}) {
      const double omega = 2 * kPi / period;
      const auto sdof =
          structure::BuildSdof(
              1.0, 2 * zeta * omega,
              hysteresis::SingleLaw(hysteresis::LawType::kLinearSpring, {omega * omega}))
              .structure;
      integrators::ResponseHistory response;
      ASSERT_TRUE(integrators::RunNewmark(sdof, excitation, {h, steps}, {}, &response).ok());
      const auto exact =
          ExactDeformationHistory(excitation.ground[0].acceleration, period, zeta, substeps);
      ASSERT_EQ(exact.size(), std::size_t(steps + 1));
      double peak_newmark = 0, peak_exact = 0, worst = 0;
      for (int k = 0; k <= steps; ++k) {
        peak_newmark = std::max(peak_newmark, std::abs(response.displacement(k, 0)));
        peak_exact = std::max(peak_exact, std::abs(exact[k]));
        worst = std::max(worst, std::abs(response.displacement(k, 0) - exact[k]));
      }
      EXPECT_NEAR(peak_newmark / peak_exact, 1.0, 2e-4) << "T " << period << " zeta " << zeta;
      EXPECT_LT(worst / peak_exact, 5e-4) << "T " << period << " zeta " << zeta;
      std::printf("T = %.1f s, zeta = %.2f: D exact %.6g m, Newmark %.6g m, history %.1e\n", period,
                  zeta, peak_exact, peak_newmark, worst / peak_exact);
    }
  }
}

}  // namespace
}  // namespace isolab::spectra
