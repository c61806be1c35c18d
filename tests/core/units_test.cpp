#include "isolab/core/units.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace isolab {
namespace {

TEST(UnitSystem, ConvertsQuantitiesIntoTheModelsUnits) {
  const UnitSystem kn_mm("kN", "mm", "s");
  EXPECT_DOUBLE_EQ(kn_mm.Parse("0.2 kN/mm", dimension::kStiffness), 0.2);
  EXPECT_DOUBLE_EQ(kn_mm.Parse("200 kN/m", dimension::kStiffness), 0.2);
  EXPECT_DOUBLE_EQ(kn_mm.Parse("3.5", dimension::kStiffness), 3.5);  // bare: model units
  // Mass unit kN s^2/mm = 1e6 kg = 1000 t.
  EXPECT_DOUBLE_EQ(kn_mm.Parse("250 t", dimension::kMass), 0.25);
  EXPECT_DOUBLE_EQ(kn_mm.Parse("1 g", dimension::kAcceleration), 9806.65);
  EXPECT_DOUBLE_EQ(kn_mm.Parse("0.5 m", dimension::kLength), 500.0);
  const UnitSystem kip_in("kip", "in", "s");
  // Chopra: 100 kip / g = 100 / 386.09 kip s^2/in.
  EXPECT_NEAR(kip_in.Convert(1.0, "g", dimension::kAcceleration), 386.0886, 1e-4);
  EXPECT_NEAR(kip_in.Parse("1 kip*s^2/in", dimension::kMass), 1.0, 1e-15);
  EXPECT_NEAR(UnitSystem("N", "m").Parse("1 kip/in", dimension::kStiffness), 175126.8, 0.1);
}

TEST(UnitSystem, RejectsUnknownAndMismatchedUnits) {
  const UnitSystem kn_mm("kN", "mm", "s");
  EXPECT_THROW(kn_mm.Parse("3 furlong", dimension::kLength), std::invalid_argument);
  try {
    kn_mm.Parse("2 kN/s", dimension::kStiffness);
    FAIL();
  } catch (const std::invalid_argument& error) {
    EXPECT_STREQ(error.what(), "'kN/s' is a mass^1 length^1 time^-3 unit, expected force/length");
  }
  EXPECT_THROW(UnitSystem("kilonewton", "mm"), std::invalid_argument);
  EXPECT_THROW(kn_mm.Parse("kN", dimension::kForce), std::invalid_argument);
}

}  // namespace
}  // namespace isolab
