#include "isolab/core/units.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace isolab {
namespace {

struct UnitSymbol {
  std::string_view symbol;
  double si;  // size in SI
  Dimension dimension;
};

constexpr double kStandardGravity = 9.80665;  // m/s^2
constexpr double kInch = 0.0254, kPoundForce = 4.4482216152605;

constexpr UnitSymbol kUnits[] = {
    {"N", 1.0, dimension::kForce},
    {"kN", 1e3, dimension::kForce},
    {"MN", 1e6, dimension::kForce},
    {"lbf", kPoundForce, dimension::kForce},
    {"kip", 1e3 * kPoundForce, dimension::kForce},
    {"m", 1.0, dimension::kLength},
    {"cm", 1e-2, dimension::kLength},
    {"mm", 1e-3, dimension::kLength},
    {"in", kInch, dimension::kLength},
    {"ft", 12 * kInch, dimension::kLength},
    {"s", 1.0, dimension::kTime},
    {"ms", 1e-3, dimension::kTime},
    {"kg", 1.0, dimension::kMass},
    {"t", 1e3, dimension::kMass},
    {"g", kStandardGravity, dimension::kAcceleration},  // standard gravity, not the gram
    {"gal", 1e-2, dimension::kAcceleration},
};

const UnitSymbol* Find(std::string_view symbol) {
  for (const UnitSymbol& unit : kUnits) {
    if (unit.symbol == symbol) return &unit;
  }
  return nullptr;
}

Dimension Scale(Dimension d, int power) {
  return {d.mass * power, d.length * power, d.time * power};
}
Dimension Add(Dimension a, Dimension b) {
  return {a.mass + b.mass, a.length + b.length, a.time + b.time};
}

// A product of symbols with optional integer powers, separated by '*' or '/':
// "kN*s^2/mm", "m/s^2", "t".
void ParseUnitExpression(std::string_view text, double* si, Dimension* dim) {
  *si = 1.0;
  *dim = dimension::kNone;
  int sign = 1;
  std::size_t i = 0;
  if (text.empty()) throw std::invalid_argument("missing unit");
  while (i < text.size()) {
    std::size_t end = i;
    while (end < text.size() && text[end] != '*' && text[end] != '/' && text[end] != '^') ++end;
    const std::string_view symbol = text.substr(i, end - i);
    if (symbol.empty()) throw std::invalid_argument(fmt::format("a unit is missing in '{}'", text));
    const UnitSymbol* unit = Find(symbol);
    if (unit == nullptr) throw std::invalid_argument(fmt::format("unknown unit '{}'", symbol));
    int power = 1;
    i = end;
    if (i < text.size() && text[i] == '^') {
      ++i;
      const auto [last, error] = std::from_chars(text.data() + i, text.data() + text.size(), power);
      if (error != std::errc()) throw std::invalid_argument(fmt::format("bad power in '{}'", text));
      i = static_cast<std::size_t>(last - text.data());
    }
    *si *= std::pow(unit->si, sign * power);
    *dim = Add(*dim, Scale(unit->dimension, sign * power));
    if (i < text.size()) {
      sign = text[i] == '/' ? -1 : 1;
      ++i;
    }
  }
}

double FactorOf(std::string_view symbol, Dimension expected) {
  const UnitSymbol* unit = Find(symbol);
  if (unit == nullptr || !(unit->dimension == expected)) {
    throw std::invalid_argument(
        fmt::format("'{}' is not a {} unit", symbol, DescribeDimension(expected)));
  }
  return unit->si;
}

}  // namespace

std::string DescribeDimension(Dimension d) {
  if (d == dimension::kNone) return "dimensionless";
  if (d == dimension::kForce) return "force";
  if (d == dimension::kLength) return "length";
  if (d == dimension::kTime) return "time";
  if (d == dimension::kMass) return "mass";
  if (d == dimension::kStiffness) return "force/length";
  if (d == dimension::kDampingCoefficient) return "force*time/length";
  if (d == dimension::kAcceleration) return "acceleration";
  if (d == dimension::kVelocity) return "velocity";
  return fmt::format("mass^{} length^{} time^{}", d.mass, d.length, d.time);
}

std::string DescribeUnits(const UnitSystem& units, Dimension d) {
  // Mass enters as force * time^2 / length.
  const int force = d.mass, length = d.length - d.mass, time = d.time + 2 * d.mass;
  std::string numerator, denominator;
  const auto add = [](std::string* side, const std::string& unit, int power) {
    if (power == 0) return;
    const std::string factor = power == 1 ? unit : fmt::format("{}^{}", unit, power);
    *side = side->empty() ? factor : fmt::format("{}*{}", *side, factor);
  };
  add(force > 0 ? &numerator : &denominator, units.force(), std::abs(force));
  add(length > 0 ? &numerator : &denominator, units.length(), std::abs(length));
  add(time > 0 ? &numerator : &denominator, units.time(), std::abs(time));
  if (numerator.empty()) numerator.assign(1, denominator.empty() ? '-' : '1');
  return denominator.empty() ? numerator : fmt::format("{}/{}", numerator, denominator);
}

UnitSystem::UnitSystem(std::string force, std::string length, std::string time)
    : force_(std::move(force)),
      length_(std::move(length)),
      time_(std::move(time)),
      force_si_(FactorOf(force_, dimension::kForce)),
      length_si_(FactorOf(length_, dimension::kLength)),
      time_si_(FactorOf(time_, dimension::kTime)) {}

double UnitSystem::SiFactor(Dimension d) const {
  const double mass_si = force_si_ * time_si_ * time_si_ / length_si_;
  return std::pow(mass_si, d.mass) * std::pow(length_si_, d.length) * std::pow(time_si_, d.time);
}

double UnitSystem::Parse(std::string_view text, Dimension expected) const {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  if (begin != end && *begin == '+') ++begin;
  const auto [last, error] = std::from_chars(begin, end, value);
  if (error != std::errc() || last == begin) {
    throw std::invalid_argument(fmt::format("'{}' is not a number with a unit", text));
  }
  if (!std::isfinite(value)) {
    throw std::invalid_argument(fmt::format("'{}' is not a finite number", text));
  }
  std::string_view unit(last, static_cast<std::size_t>(end - last));
  while (!unit.empty() && unit.front() == ' ') unit.remove_prefix(1);
  if (unit.empty()) return value;  // a bare number is in the model's units
  return Convert(value, unit, expected);
}

double UnitSystem::Convert(double value, std::string_view unit, Dimension expected) const {
  double si = 1.0;
  Dimension dim;
  ParseUnitExpression(unit, &si, &dim);
  if (!(dim == expected)) {
    throw std::invalid_argument(fmt::format("'{}' is a {} unit, expected {}", unit,
                                            DescribeDimension(dim), DescribeDimension(expected)));
  }
  return value * si / SiFactor(expected);
}

}  // namespace isolab
