// The header scanners that replaced std::regex (src/io/record_header.h): they match what the
// regexes matched (PEER's NPTS/DT in any spacing and case, the oldest layout only at the line's
// start, Peknold's sampling sentence), find units only in a units statement, and walk a line
// once: a megabyte of near-misses is scanned, not backtracked.
#include "record_header.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>

namespace isolab::io {
namespace {

void ExpectSampling(const std::optional<HeaderSampling>& found, const std::string& points,
                    const std::string& step) {
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->points, points);
  EXPECT_EQ(found->step, step);
}

TEST(RecordHeader, NptsAndDtInAnySpacingAndCase) {
  ExpectSampling(FindNptsDt("NPTS=  1560, DT= .02000 SEC"), "1560", ".02000");
  ExpectSampling(FindNptsDt("NPTS=3000,DT=0.01"), "3000", "0.01");
  ExpectSampling(FindNptsDt("npts = 12 dt = 1.5D-02 sec"), "12", "1.5D-02");
  // The first NPTS lacks its DT: the second is the statement.
  ExpectSampling(FindNptsDt("NPTS= 5 then NPTS= 7, DT= 0.1"), "7", "0.1");
  EXPECT_FALSE(FindNptsDt("NPTS= 12, DT"));
  EXPECT_FALSE(FindNptsDt("NPTS 12, DT= 0.1"));
  EXPECT_FALSE(FindNptsDt("NPTS= , DT= 0.1"));
}

TEST(RecordHeader, OldestLayoutOnlyOpeningTheLine) {
  ExpectSampling(FindOldestSampling(" 5 0.005 NPTS, DT"), "5", "0.005");
  ExpectSampling(FindOldestSampling("4000\t.01E0 npts ,dt"), "4000", ".01E0");
  EXPECT_FALSE(FindOldestSampling("x 5 0.005 NPTS, DT"));
  EXPECT_FALSE(FindOldestSampling("5 0.005NPTS, DT"));
  EXPECT_FALSE(FindOldestSampling("5 0.005 NPTS DT"));
}

TEST(RecordHeader, PeknoldSamplingSentence) {
  ExpectSampling(FindPeknoldSampling("1559 points at equal spacing of 0.02 sec"), "1559", "0.02");
  ExpectSampling(FindPeknoldSampling("n=1559  POINTS AT EQUAL SPACING OF  .02SEC"), "1559", ".02");
  EXPECT_FALSE(FindPeknoldSampling("1559points at equal spacing of 0.02 sec"));
  EXPECT_FALSE(FindPeknoldSampling("points at equal spacing of 0.02 sec"));
  EXPECT_FALSE(FindPeknoldSampling("1559 points at equal spacing of 0.02"));
}

TEST(RecordHeader, UnitsOnlyFromAUnitsStatement) {
  const auto unit_of = [](std::string_view line) -> std::string {
    const auto statement = FindUnitsStatement(line);
    return statement ? std::string(statement->unit) : "(none)";
  };
  EXPECT_EQ(unit_of("ACCELERATION TIME SERIES IN UNITS OF G"), "G");
  EXPECT_EQ(unit_of("ACCELERATION TIME HISTORY IN UNITS OF G. FILTER POINTS: HP=0.1 Hz"), "G");
  EXPECT_EQ(unit_of("IN UNITS OF G; A(0) = 0 AT T = 0"), "G");
  EXPECT_EQ(unit_of("ACCELERATION TIME SERIES IN UNITS OF CM/S/S"), "CM/S/S");
  EXPECT_EQ(unit_of("The units are (g)"), "g");
  EXPECT_EQ(unit_of("ACCELERATION IN G"), "G");
  EXPECT_EQ(unit_of("UNITS OF FURLONGS"), "FURLONGS");
  // Prose is no statement, whatever units it mentions.
  EXPECT_EQ(unit_of("Test earthquake, peak 0.3 g, in g as everyone knows"), "(none)");
  EXPECT_EQ(unit_of("The units are consistent with the g of the description"), "(none)");
  EXPECT_EQ(unit_of("ACCELERATION IN THE NORTH DIRECTION"), "(none)");
  EXPECT_EQ(unit_of("PEAK ACCELERATION IN G"), "(none)");
  const auto statement = FindUnitsStatement("ACCELERATION TIME SERIES IN UNITS OF FT/S^2, 0.3 g");
  ASSERT_TRUE(statement);
  EXPECT_EQ(statement->statement, "UNITS OF FT/S^2");
}

TEST(RecordHeader, CsvUnitsAreTheValueColumns) {
  EXPECT_EQ(FindCsvUnits("time (s),acc (m/s^2)")->unit, "m/s^2");
  EXPECT_EQ(FindCsvUnits("time,acc ( g )")->unit, "g");
  EXPECT_EQ(FindCsvUnits("acc (g")->unit, "g");
  EXPECT_FALSE(FindCsvUnits("time (s),acc"));
}

TEST(RecordHeader, AMegabyteOfNearMissesIsScannedOnce) {
  // Each "NPTS= 1," starts an attempt that fails at the next NPTS; std::regex backtracked over
  // such lines (12 s for 20 kB). No timing here: a quadratic scan would hit ctest's timeout.
  std::string near_misses;
  while (near_misses.size() < (1u << 20)) near_misses += "NPTS= 1, points at equal spacing of ";
  EXPECT_FALSE(FindNptsDt(near_misses));
  EXPECT_FALSE(FindPeknoldSampling(near_misses));
  EXPECT_FALSE(FindOldestSampling(std::string(1u << 20, '9')));
  EXPECT_FALSE(FindUnitsStatement(near_misses));
}

}  // namespace
}  // namespace isolab::io
