// Shake-table CSV: each column's unit from its name's suffix or from brackets, converted to the
// caller's units on request (against hand conversions: 1 g = 9.80665 m/s^2, 981 cm/s^2 =
// 9.81 m/s^2), comments skipped, and a channel asked for in the wrong dimension refused with its
// header line and column.
#include "isolab/io/shake_table_file.h"

#include <gtest/gtest.h>

#include <cstdio>
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

// Times printed to five decimals at 300 Hz (0.00333, 0.00667, 0.01) are a uniform step; a lost
// sample is not, and is named at its line against the median step.
TEST(ShakeTableFile, TimesMustBeEvenlySpaced) {
  std::string rounded = "time_s,a1_g\n", lost = rounded;
  for (int k = 0; k < 30; ++k) {
    char line[64];
    std::snprintf(line, sizeof line, "%.5f,0\n", k / 300.0);
    rounded += line;
    if (k != 12) lost += line;
  }
  EXPECT_EQ(ShakeTableData::Read(Write("rounded.csv", rounded)).time().size(), 30u);
  try {
    ShakeTableData::Read(Write("lost.csv", lost));
    FAIL() << "a lost sample was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().line, 14);  // the sample after the lost one (k = 13)
    EXPECT_EQ(error.location().column, 1);
    EXPECT_NE(std::string(error.what())
                  .find("time 0.04333 follows 0.03667: a step of 0.00666 s where the "
                        "samples are 0.00333 s apart"),
              std::string::npos)
        << error.what();
  }
}

TEST(ShakeTableFile, AnAccelerationAbove10gIsACorruptValue) {
  const ShakeTableData data =
      ShakeTableData::Read(Write("spike.csv", "time_s,a1 [g],d1 [mm]\n0,0.5,3\n0.01,10.5,4\n"));
  const UnitSystem si("kN", "m", "s");
  try {
    data.Channel("a1", dimension::kAcceleration, si);
    FAIL() << "10.5 g was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.location().line, 3);
    EXPECT_EQ(error.location().column, 2);
  }
  EXPECT_NEAR(data.Channel("d1", dimension::kLength, si)[1], 0.004, 1e-15);
}

}  // namespace
}  // namespace isolab::io
