// Units of a model file. A model declares force, length and time units; every number in it is in
// those units (mass in force*time^2/length), and any quantity may instead be a string with its own
// unit, "0.2 kN/mm", "250 t", "0.35 g", converted to the model's units on reading.
#pragma once

#include <string>
#include <string_view>

namespace isolab {

// Exponents of mass, length and time.
struct Dimension {
  int mass = 0, length = 0, time = 0;
  bool operator==(const Dimension&) const = default;
};

namespace dimension {
inline constexpr Dimension kNone{0, 0, 0};
inline constexpr Dimension kLength{0, 1, 0};
inline constexpr Dimension kTime{0, 0, 1};
inline constexpr Dimension kMass{1, 0, 0};
inline constexpr Dimension kForce{1, 1, -2};
inline constexpr Dimension kStiffness{1, 0, -2};           // force/length
inline constexpr Dimension kDampingCoefficient{1, 0, -1};  // force*time/length
inline constexpr Dimension kAcceleration{0, 1, -2};
inline constexpr Dimension kVelocity{0, 1, -1};
}  // namespace dimension

// "force/length", "mass", ... for messages.
std::string DescribeDimension(Dimension dimension);

class UnitSystem;
// The model's own unit for a dimension, "kN/mm", "kN*s^2/mm", for messages and output.
std::string DescribeUnits(const UnitSystem& units, Dimension dimension);

class UnitSystem {
 public:
  // Throws std::invalid_argument naming the unit that is not a force, length or time unit.
  UnitSystem(std::string force, std::string length, std::string time = "s");

  const std::string& force() const { return force_; }
  const std::string& length() const { return length_; }
  const std::string& time() const { return time_; }

  // Size in SI of this system's unit of `dimension` (mass unit = force unit * time^2 / length).
  double SiFactor(Dimension dimension) const;

  // Converts "value unit" (or a bare number) of the given dimension into this system's units.
  // Throws std::invalid_argument: unknown unit, or a unit of another dimension.
  double Parse(std::string_view text, Dimension expected) const;

  // Converts a value given in `unit` (e.g. a record's "g" or "cm/s^2") into this system.
  double Convert(double value, std::string_view unit, Dimension expected) const;

 private:
  std::string force_, length_, time_;
  double force_si_, length_si_, time_si_;
};

}  // namespace isolab
