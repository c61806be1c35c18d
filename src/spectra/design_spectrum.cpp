// Code design spectra (design_spectrum.h): ASCE 7-16 Sec. 11.4.6, EN 1998-1 Sec. 3.2.2.2, tables.
#include "isolab/spectra/design_spectrum.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "isolab/core/errors.h"

namespace isolab::spectra {
namespace {

// S, T_B, T_C, T_D of one ground type and spectrum type.
struct Eurocode8Shape {
  double soil = 1.0;                    // S
  double tb = 0.0, tc = 0.0, td = 0.0;  // (s)
};

// EN 1998-1 Table 3.2 (type 1) and Table 3.3 (type 2), rows A to E.
constexpr Eurocode8Shape kType1[] = {{1.0, 0.15, 0.4, 2.0},
                                     {1.2, 0.15, 0.5, 2.0},
                                     {1.15, 0.20, 0.6, 2.0},
                                     {1.35, 0.20, 0.8, 2.0},
                                     {1.4, 0.15, 0.5, 2.0}};
constexpr Eurocode8Shape kType2[] = {{1.0, 0.05, 0.25, 1.2},
                                     {1.35, 0.05, 0.25, 1.2},
                                     {1.5, 0.10, 0.25, 1.2},
                                     {1.8, 0.10, 0.30, 1.2},
                                     {1.6, 0.05, 0.25, 1.2}};

Eurocode8Shape ShapeOf(const Eurocode8Spectrum& spectrum) {
  const auto row = static_cast<std::size_t>(spectrum.ground);
  return spectrum.type == 1 ? kType1[row] : kType2[row];
}

char GroundLetter(GroundType ground) { return static_cast<char>('A' + static_cast<int>(ground)); }

void RequirePositive(const char* key, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InvalidParameter({key, value, "must be finite and > 0"});
  }
}

void ValidateOne(const Asce7Spectrum& spectrum) {
  RequirePositive("sms", spectrum.sms);
  RequirePositive("sm1", spectrum.sm1);
  RequirePositive("tl", spectrum.long_period);  // the design file's key, ASCE 7's T_L
  // Below T_s the branches overlap and Sa would jump down at T_s.
  const double ts = spectrum.sm1 / spectrum.sms;
  if (spectrum.long_period < ts) {
    throw InvalidParameter(
        {"tl", spectrum.long_period, fmt::format("must be >= T_s = S_M1/S_MS = {:g} s", ts)});
  }
}

void ValidateOne(const Eurocode8Spectrum& spectrum) {
  RequirePositive("agr", spectrum.agr);
  const int ground = static_cast<int>(spectrum.ground);
  if (ground < 0 || ground > static_cast<int>(GroundType::kE)) {
    throw InvalidParameter({"ground", double(ground), "must be one of A, B, C, D, E"});
  }
  if (spectrum.type != 1 && spectrum.type != 2) {
    throw InvalidParameter({"type", double(spectrum.type), "must be 1 or 2"});
  }
  RequirePositive("importance", spectrum.importance);
  if (!(spectrum.damping_ratio >= 0.0 && spectrum.damping_ratio < 1.0)) {
    throw InvalidParameter({"damping_ratio", spectrum.damping_ratio, "must be in [0, 1)"});
  }
}

void ValidateOne(const TabulatedSpectrum& spectrum) {
  if (spectrum.periods.size() < 2) {
    throw InvalidParameter(
        {"periods", double(spectrum.periods.size()), "a table needs at least 2 points"});
  }
  if (spectrum.sa.size() != spectrum.periods.size()) {
    throw InvalidParameter(
        {"sa", double(spectrum.sa.size()),
         fmt::format("must have one value per period ({})", spectrum.periods.size())});
  }
  for (std::size_t k = 0; k < spectrum.periods.size(); ++k) {
    const double period = spectrum.periods[k];
    if (!(period >= 0.0) || !std::isfinite(period)) {
      throw InvalidParameter({fmt::format("periods[{}]", k), period, "must be finite and >= 0"});
    }
    if (k > 0 && !(period > spectrum.periods[k - 1])) {
      throw InvalidParameter({fmt::format("periods[{}]", k), period,
                              fmt::format("must be > periods[{}] = {:g} (strictly increasing)",
                                          k - 1, spectrum.periods[k - 1])});
    }
    if (!(spectrum.sa[k] >= 0.0) || !std::isfinite(spectrum.sa[k])) {
      throw InvalidParameter({fmt::format("sa[{}]", k), spectrum.sa[k], "must be finite and >= 0"});
    }
  }
}

void RequirePeriod(double period) {
  if (!(period >= 0.0) || !std::isfinite(period)) {
    throw InvalidParameter({"period", period, "must be finite and >= 0"});
  }
}

double SaOf(const Asce7Spectrum& spectrum, double period) {
  const double t0 = 0.2 * spectrum.sm1 / spectrum.sms;
  const double ts = spectrum.sm1 / spectrum.sms;
  if (period < t0) return spectrum.sms * (0.4 + 0.6 * period / t0);
  if (period <= ts) return spectrum.sms;
  if (period <= spectrum.long_period) return spectrum.sm1 / period;
  return spectrum.sm1 * spectrum.long_period / (period * period);
}

double SaOf(const Eurocode8Spectrum& spectrum, double period) {
  if (period > kEurocode8LastPeriod) {
    throw InvalidParameter({"period", period,
                            "must be <= 4 s: Eurocode 8 (EN 1998-1 Sec. 3.2.2.2) defines its "
                            "elastic spectrum up to 4 s"});
  }
  const Eurocode8Shape shape = ShapeOf(spectrum);
  const double ag = spectrum.importance * spectrum.agr;
  const double eta = DampingCorrection(spectrum.damping_ratio);
  const double plateau = ag * shape.soil * eta * 2.5;
  if (period <= shape.tb) return ag * shape.soil * (1.0 + period / shape.tb * (2.5 * eta - 1.0));
  if (period <= shape.tc) return plateau;
  if (period <= shape.td) return plateau * shape.tc / period;
  return plateau * shape.tc * shape.td / (period * period);
}

double SaOf(const TabulatedSpectrum& spectrum, double period) {
  const std::vector<double>& t = spectrum.periods;
  if (period < t.front() || period > t.back()) {
    throw InvalidParameter(
        {"period", period,
         fmt::format("must be within the table's periods, {:g} to {:g} s", t.front(), t.back())});
  }
  // The first point above `period` (or the last one): interpolate on the interval before it.
  const auto above = std::upper_bound(t.begin(), t.end(), period);
  const std::size_t k = std::min<std::size_t>(std::distance(t.begin(), above), t.size() - 1);
  const double weight = (period - t[k - 1]) / (t[k] - t[k - 1]);
  // Weighted so that the table's own points come back exactly.
  return (1.0 - weight) * spectrum.sa[k - 1] + weight * spectrum.sa[k];
}

}  // namespace

void Validate(const TargetSpectrum& spectrum) {
  std::visit([](const auto& s) { ValidateOne(s); }, spectrum);
}

double SpectralAcceleration(const TargetSpectrum& spectrum, double period) {
  Validate(spectrum);
  RequirePeriod(period);
  return std::visit([period](const auto& s) { return SaOf(s, period); }, spectrum);
}

std::string Describe(const TargetSpectrum& spectrum) {
  struct Describer {
    std::string operator()(const Asce7Spectrum& s) const {
      return fmt::format("ASCE 7-16 MCE_R: S_MS {:g} g, S_M1 {:g} g, T_L {:g} s", s.sms, s.sm1,
                         s.long_period);
    }
    std::string operator()(const Eurocode8Spectrum& s) const {
      return fmt::format(
          "Eurocode 8 type {}, ground {}: a_g {:g} g (gamma_I {:g} x a_gR {:g} g), {:g} % damping",
          s.type, GroundLetter(s.ground), s.importance * s.agr, s.importance, s.agr,
          100.0 * s.damping_ratio);
    }
    std::string operator()(const TabulatedSpectrum& s) const {
      if (s.periods.empty()) return fmt::format("table from {}, empty", s.source);
      return fmt::format("table from {}, {:g} to {:g} s", s.source, s.periods.front(),
                         s.periods.back());
    }
  };
  return std::visit(Describer{}, spectrum);
}

std::vector<double> CornerPeriods(const TargetSpectrum& spectrum) {
  Validate(spectrum);
  struct Corners {
    std::vector<double> operator()(const Asce7Spectrum& s) const {
      return {0.2 * s.sm1 / s.sms, s.sm1 / s.sms, s.long_period};
    }
    std::vector<double> operator()(const Eurocode8Spectrum& s) const {
      const Eurocode8Shape shape = ShapeOf(s);
      return {shape.tb, shape.tc, shape.td};
    }
    std::vector<double> operator()(const TabulatedSpectrum& s) const { return s.periods; }
  };
  return std::visit(Corners{}, spectrum);
}

double DampingCorrection(double damping_ratio) {
  return std::max(std::sqrt(10.0 / (5.0 + 100.0 * damping_ratio)), 0.55);
}

double ContinuedSpectralAcceleration(const TargetSpectrum& spectrum, double period) {
  double first = 0.0, last = kEurocode8LastPeriod;
  if (const auto* table = std::get_if<TabulatedSpectrum>(&spectrum)) {
    first = table->periods.front();
    last = table->periods.back();
  } else if (!std::holds_alternative<Eurocode8Spectrum>(spectrum)) {
    return SpectralAcceleration(spectrum, period);
  }
  if (period > last)
    return SpectralAcceleration(spectrum, last) * (last / period) * (last / period);
  return SpectralAcceleration(spectrum, std::max(period, first));
}

}  // namespace isolab::spectra
