#include "isolab/analysis/synthetic_motion.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "isolab/io/atomic_file.h"

namespace isolab::analysis {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Standard normal deviates from mt19937_64 by Box-Muller (the generator's sequence is fixed by the
// standard; std::normal_distribution's algorithm is not).
class GaussianNoise {
 public:
  explicit GaussianNoise(std::uint64_t seed) : engine_(seed) {}
  double Next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = (static_cast<double>(engine_() >> 11) + 1.0) * 0x1.0p-53;  // (0, 1]
    const double u2 = static_cast<double>(engine_() >> 11) * 0x1.0p-53;          // [0, 1)
    const double radius = std::sqrt(-2.0 * std::log(u1));
    spare_ = radius * std::sin(kTwoPi * u2);
    has_spare_ = true;
    return radius * std::cos(kTwoPi * u2);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// A second-order filter x'' + 2 z w x' + w^2 x = input, advanced by RK4 with the input held
// over the step; returns the state after each call.
struct Oscillator {
  double w, z, x = 0.0, v = 0.0;
  void Step(double input, double h) {
    const auto f = [&](double xi, double vi) { return input - 2 * z * w * vi - w * w * xi; };
    const double k1x = v, k1v = f(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = f(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = f(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = f(x + h * k3x, v + h * k3v);
    x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
};

// A record of `samples` zeros in g at `dt`, to be filled.
io::Record EmptyRecord(int samples, double dt) {
  io::Record record;
  record.dt = dt;
  record.units = "g";
  record.format = "PEER AT2";
  record.values.assign(samples, 0.0);
  return record;
}

}  // namespace

io::Record FilteredNoiseRecord(const FilteredNoiseSpec& spec) {
  const int samples = static_cast<int>(std::round(spec.duration / spec.dt)) + 1;
  GaussianNoise noise(spec.seed);
  Oscillator site{kTwoPi * spec.site_frequency, spec.site_damping};
  Oscillator high_pass{kTwoPi * spec.high_pass_frequency, spec.high_pass_damping};
  io::Record record = EmptyRecord(samples, spec.dt);
  for (int k = 0; k < samples; ++k) {
    const double t = k * spec.dt;
    // Kanai-Tajimi: the site oscillator's absolute acceleration; Clough-Penzien: its high-pass.
    site.Step(noise.Next() / std::sqrt(spec.dt), spec.dt);
    const double kanai_tajimi = -(2 * site.z * site.w * site.v + site.w * site.w * site.x);
    high_pass.Step(kanai_tajimi, spec.dt);
    const double filtered = high_pass.w * high_pass.w * high_pass.x;  // removes the low end
    const double envelope = t < spec.rise_end      ? (t / spec.rise_end) * (t / spec.rise_end)
                            : t <= spec.strong_end ? 1.0
                                                   : std::exp(-spec.decay * (t - spec.strong_end));
    record.values[k] = envelope * (kanai_tajimi - filtered) + 0.0;  // + 0.0: no "-0" samples
  }
  const double peak =
      std::abs(*std::max_element(record.values.begin(), record.values.end(),
                                 [](double a, double b) { return std::abs(a) < std::abs(b); }));
  for (double& value : record.values) value *= spec.pga / peak;
  record.description = fmt::format(
      "isolab filtered white noise, seed {}: Kanai-Tajimi fg = {:g} Hz zg = {:g}, Clough-Penzien "
      "ff = {:g} Hz zf = {:g}, Jennings envelope t1 = {:g} s t2 = {:g} s c = {:g}/s, PGA {:g} g",
      spec.seed, spec.site_frequency, spec.site_damping, spec.high_pass_frequency,
      spec.high_pass_damping, spec.rise_end, spec.strong_end, spec.decay, spec.pga);
  return record;
}

io::Record PulseRecord(const PulseSpec& spec) {
  const int samples = static_cast<int>(std::round(spec.duration / spec.dt)) + 1;
  const double fp = 1.0 / spec.period, half_width = spec.oscillations / (2.0 * fp);
  constexpr double kGravity = 9.80665;
  io::Record record = EmptyRecord(samples, spec.dt);
  for (int k = 0; k < samples; ++k) {
    const double s = k * spec.dt - spec.peak_time;
    if (std::abs(s) > half_width) continue;
    const double a = kTwoPi * fp / spec.oscillations, b = kTwoPi * fp;
    // d/dt of A/2 [1 + cos(a s)] cos(b s + nu)
    const double acceleration = -0.5 * spec.pgv *
                                (a * std::sin(a * s) * std::cos(b * s + spec.phase) +
                                 (1 + std::cos(a * s)) * b * std::sin(b * s + spec.phase));
    record.values[k] = acceleration / kGravity;
  }
  record.description = fmt::format(
      "isolab near-fault pulse (Mavroeidis & Papageorgiou 2003): Tp = {:g} s, PGV = {:g} m/s, "
      "gamma = {:g}, nu = {:g} rad, t0 = {:g} s",
      spec.period, spec.pgv, spec.oscillations, spec.phase, spec.peak_time);
  return record;
}

void WriteAt2(const io::Record& record, const std::string& path) {
  // A record `isolab run` would refuse is never written: the callers' option checks keep the
  // samples finite and at least two, and this says which sample if one slips through.
  if (record.values.size() < 2) {
    throw std::invalid_argument(
        fmt::format("{}: a record of {} samples", path, record.values.size()));
  }
  for (std::size_t k = 0; k < record.values.size(); ++k) {
    if (!std::isfinite(record.values[k])) {
      throw std::invalid_argument(
          fmt::format("{}: sample {} of the record is {}", path, k + 1, record.values[k]));
    }
  }
  io::WriteTextFileAtomically(path, [&](std::ostream& out) {
    fmt::print(out, "PEER NGA STRONG MOTION DATABASE RECORD (layout only: synthetic)\n");
    fmt::print(out, "{}\n", record.description);
    fmt::print(out, "ACCELERATION TIME SERIES IN UNITS OF G\n");
    fmt::print(out, "NPTS= {:7d}, DT= {:9.5f} SEC,\n", record.values.size(), record.dt);
    for (std::size_t k = 0; k < record.values.size(); ++k) {
      // A space before every value: a three-digit exponent ("-4.6249845E-100", 15 characters)
      // would otherwise run into the value before it. Two-digit ones keep PEER's 15 columns.
      fmt::print(out, " {:14.7E}{}", record.values[k],
                 (k % 5 == 4 || k + 1 == record.values.size()) ? "\n" : "");
    }
  });
}

}  // namespace isolab::analysis
