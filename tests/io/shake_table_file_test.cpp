// Shake-table CSV: each column's unit from its name's suffix or from brackets, converted to the
// caller's units on request (against hand conversions: 1 g = 9.80665 m/s^2, 981 cm/s^2 =
// 9.81 m/s^2), comments skipped, and a channel asked for in the wrong dimension refused with its
// header line and column.
#include "isolab/io/shake_table_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "isolab/core/errors.h"
#include "own_test_file.h"

namespace isolab::io {
namespace {

std::string Write(const std::string& name, const std::string& text) {
  const auto path = isolab::testing::OwnTestDirectory() / name;
  std::ofstream(path) << text;
  return path.string();
}

TEST(ShakeTableFile, ReadsUnitsFromSuffixesAndBrackets) {
  const std::string path = Write("units.csv",
                                 "# a comment\n"
                                 "time_s,a1_g,a2 (cm/s^2),d1 [mm],d2_m\n"
                                 "0.00,0.5,981,12,0.012\n"
                                 "0.01,-1,0,0,0\n");
  const ShakeTableData data = ShakeTableData::Read(path);
  ASSERT_EQ(data.time().size(), 2u);
  EXPECT_DOUBLE_EQ(data.time()[1], 0.01);
  ASSERT_EQ(data.columns().size(), 4u);
  EXPECT_EQ(data.columns()[1].name, "a2");
  EXPECT_EQ(data.columns()[1].unit, "cm/s^2");
  const UnitSystem si("kN", "m", "s");
  EXPECT_NEAR(data.Channel("a1", dimension::kAcceleration, si)[0], 0.5 * 9.80665, 1e-12);
  EXPECT_NEAR(data.Channel("a2", dimension::kAcceleration, si)[0], 9.81, 1e-12);
  const UnitSystem mm("kN", "mm", "s");
  EXPECT_NEAR(data.Channel("d1", dimension::kLength, mm)[0], 12.0, 1e-12);
  EXPECT_NEAR(data.Channel("d2", dimension::kLength, mm)[0], 12.0, 1e-12);
  EXPECT_TRUE(data.Has("d2"));
  EXPECT_FALSE(data.Has("d3"));
  try {
    data.Channel("d1", dimension::kAcceleration, si);
    FAIL() << "a length read as an acceleration";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().line, 2);
    EXPECT_EQ(error.location().column, 4);
  }
}

}  // namespace
}  // namespace isolab::io
