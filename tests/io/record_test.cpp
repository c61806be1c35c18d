#include "isolab/io/record.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "isolab/core/errors.h"
#include "isolab/core/units.h"
#include "own_test_file.h"
#include "reference_data.h"

namespace isolab::io {
namespace {

std::string DataFile(const std::string& name) {
  return std::string(ISOLAB_TEST_DATA_DIR) + "/io/data/" + name;
}

std::string ErrorOf(const std::string& path, const RecordOptions& options = {}) {
  try {
    ReadRecord(path, options);
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << path << " read without error";
  return {};
}

// A record written into a directory of the test's own, its second line `long_line`.
std::string RecordWithLine(const std::string& name, const std::string& long_line) {
  const std::filesystem::path path = testing::OwnTestFile(name);
  std::ofstream(path) << "PEER NGA STRONG MOTION DATABASE RECORD\n"
                      << long_line << "\n"
                      << "ACCELERATION TIME SERIES IN UNITS OF G\n"
                      << "NPTS=      3, DT=   .0100 SEC,\n"
                      << "  1.0  -2.0  3.0\n";
  return path.string();
}

struct FormatCase {
  std::string file, format;
  std::size_t points;
  double dt, first, last;
};

TEST(ReadRecord, ReadsEveryAt2Layout) {
  // The header layouts of PEER's old database, NGA-West2, the oldest PEER files and the Peknold
  // files, with made-up values (tests/io/data).
  const FormatCase cases[] = {
      {"record_peer_old.at2", "PEER AT2", 7, 0.02, .3241473E-02, -.4E-01},
      {"record_ngaw2.at2", "PEER AT2", 6, 0.01, .9984852E-03, -.1790158E-03},
      {"record_oldest.at2", "PEER AT2", 5, 0.005, 0.01, 0.05},
      {"record_peknold.at2", "Peknold AT2", 9, 0.02, 0.00630, -0.00128},
  };
  for (const FormatCase& expected : cases) {
    const Record record = ReadRecord(DataFile(expected.file));
    EXPECT_EQ(record.format, expected.format) << expected.file;
    EXPECT_EQ(record.units, "g") << expected.file;
    EXPECT_EQ(record.units_source, "header") << expected.file;
    EXPECT_EQ(record.values.size(), expected.points) << expected.file;
    EXPECT_NEAR(record.dt, expected.dt, 1e-12) << expected.file;
    EXPECT_DOUBLE_EQ(record.values.front(), expected.first) << expected.file;
    EXPECT_DOUBLE_EQ(record.values.back(), expected.last) << expected.file;
  }
}

TEST(ReadRecord, BundledElCentroIsChoprasRecord) {
  // Chopra, Dynamics of Structures, Sec. 6.1: El Centro 1940 NS, 0.02 s samples, PGA 0.319 g.
  const Record record = ReadRecord(testing::ElCentroPath().string());
  EXPECT_EQ(record.format, "PEER AT2");
  EXPECT_EQ(record.units, "g");
  EXPECT_DOUBLE_EQ(record.dt, 0.02);
  ASSERT_EQ(record.values.size(), 1560u);  // a(0) = 0 and the 1559 digitised points
  EXPECT_EQ(record.values[0], 0.0);
  EXPECT_DOUBLE_EQ(record.values[1], 0.00630);
  EXPECT_NEAR(record.Peak(), 0.319, 0.0005);
  const auto peak = std::max_element(record.values.begin(), record.values.end(),
                                     [](double a, double b) { return std::abs(a) < std::abs(b); });
  EXPECT_NEAR(record.dt * static_cast<double>(peak - record.values.begin()), 2.04, 1e-9);
}

TEST(ReadRecord, ColumnsWithAndWithoutHeader) {
  const Record csv = ReadRecord(DataFile("record_with_header.csv"));
  EXPECT_EQ(csv.units, "m/s^2");
  EXPECT_DOUBLE_EQ(csv.dt, 0.01);
  EXPECT_EQ(csv.values, (std::vector<double>{0, 0.5, -0.25}));
  const Record single = ReadRecord(DataFile("record_single_column.txt"), {"cm/s^2", 0.005});
  EXPECT_EQ(single.format, "single-column");
  EXPECT_DOUBLE_EQ(single.dt, 0.005);
  EXPECT_EQ(single.values.size(), 3u);
}

// Each value is the double strtod reads from its token, however it is spelled and separated.
TEST(ReadRecord, EveryValueIsTheDoubleStrtodReads) {
  const std::vector<std::string> tokens = {"1.",
                                           ".5",
                                           "-0",
                                           "+2.5",
                                           "1e-3",
                                           "1E+03",
                                           "-7.0000000000000007e-01",
                                           "0.1",
                                           "1.5e300",
                                           "-2.2e-300",
                                           "3",
                                           "0.30000000000000004",
                                           "123456789012345678901234"};
  const std::vector<std::string> separators = {"  ", ",", "\t", " , "};
  std::string text =
      "ACCELERATION TIME SERIES IN UNITS OF G\nNPTS=" + std::to_string(tokens.size()) +
      ", DT= .01 SEC\n";
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    text += separators[k % separators.size()] + tokens[k] + (k % 3 == 2 ? "\r\n" : "");
  }
  const std::filesystem::path path = testing::OwnTestFile("spellings.at2");
  std::ofstream(path, std::ios::binary) << text << "\n";
  const Record record = ReadRecord(path.string());
  ASSERT_EQ(record.values.size(), tokens.size());
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const double expected = std::strtod(tokens[k].c_str(), nullptr);
    EXPECT_EQ(std::memcmp(&record.values[k], &expected, sizeof expected), 0)
        << tokens[k] << ": " << record.values[k] << " against " << expected;
  }
}

TEST(ReadRecord, HeaderUnitsAreWholeWordsAndFortranExponentsCount) {
  const Record gal = ReadRecord(DataFile("record_gal_fortran_dt.at2"));
  EXPECT_EQ(gal.units, "cm/s^2");   // "GAL" is not g
  EXPECT_DOUBLE_EQ(gal.dt, 0.005);  // ".5D-02"
  const Record mm = ReadRecord(DataFile("record_mm_rounded_times.csv"));
  EXPECT_EQ(mm.units, "mm/s^2");        // not m/s^2
  EXPECT_NEAR(mm.dt, 0.01 / 3, 1e-12);  // times printed to 5 decimals
  EXPECT_NE(ErrorOf(DataFile("bad_record_header.at2")).find("bad_record_header.at2:4: '"),
            std::string::npos)
      << ErrorOf(DataFile("bad_record_header.at2"));
}

TEST(ReadRecord, GivenUnitsAndStepMustAgreeWithTheFile) {
  // A gal record read as m/s^2 is 100 times too strong: refused, naming both units.
  const std::string gal = ErrorOf(DataFile("record_gal_fortran_dt.at2"), {"m/s^2", 0, "--units"});
  EXPECT_NE(gal.find("its header gives the units as cm/s^2 but --units gives m/s^2"),
            std::string::npos)
      << gal;
  // Agreeing units (another spelling) are fine and the header is named as their source.
  const Record agreed = ReadRecord(DataFile("record_gal_fortran_dt.at2"), {"gal", 0, "--units"});
  EXPECT_EQ(agreed.units, "cm/s^2");
  EXPECT_EQ(agreed.units_source, "header");
  // Where the header is silent, the given units apply and say where they came from.
  const Record given =
      ReadRecord(DataFile("record_single_column.txt"), {"cm/s^2", 0.005, "the study", "dt"});
  EXPECT_EQ(given.units_source, "the study");
  EXPECT_NE(ErrorOf(DataFile("record_single_column.txt"), {"kN", 0.005, "--units"})
                .find("--units: 'kN' is a force unit"),
            std::string::npos);
  // A step that disagrees with the header's, or with the times', is refused too.
  const std::string header_dt =
      ErrorOf(DataFile("record_ngaw2.at2"), {"", 0.02, "", "excitation.ground_motion.dt"});
  EXPECT_NE(header_dt.find("its header gives a step of 0.01 s but excitation.ground_motion.dt "
                           "gives 0.02 s"),
            std::string::npos)
      << header_dt;
  EXPECT_NE(ErrorOf(DataFile("record_with_header.csv"), {"", 0.02, "", "--record-dt"})
                .find("its times give a step of 0.01 s but --record-dt gives 0.02 s"),
            std::string::npos);
  EXPECT_DOUBLE_EQ(ReadRecord(DataFile("record_ngaw2.at2"), {"", 0.01}).dt, 0.01);
}

TEST(ReadRecord, BadRecordsNameFileLineAndProblem) {
  EXPECT_NE(ErrorOf(DataFile("bad_record_nan.at2")).find("bad_record_nan.at2:6: 'nan' is not a"),
            std::string::npos)
      << ErrorOf(DataFile("bad_record_nan.at2"));
  EXPECT_NE(
      ErrorOf(DataFile("bad_record_count.at2")).find("declares 5 points but the file holds 4"),
      std::string::npos);
  EXPECT_NE(ErrorOf(DataFile("bad_record_empty.txt")).find("the record is empty"),
            std::string::npos);
  EXPECT_NE(
      ErrorOf(DataFile("bad_record_token.txt"), {"g", 0.01}).find("bad_record_token.txt:3: '0.2x'"),
      std::string::npos);
  EXPECT_NE(
      ErrorOf(DataFile("record_single_column.txt"), {"g", 0.0}).find("sampling step is unknown"),
      std::string::npos);
  EXPECT_NE(
      ErrorOf(DataFile("record_single_column.txt"), {"", 0.01}).find("units are not in its header"),
      std::string::npos);
  EXPECT_NE(ErrorOf(DataFile("bad_record_uneven.txt"), {"g", 0}).find("uniform step"),
            std::string::npos);
  EXPECT_NE(ErrorOf(DataFile("no_such_record.at2")).find("cannot open"), std::string::npos);
  // A directory used to read as an empty record.
  EXPECT_NE(ErrorOf(DataFile("")).find("is a directory, not a record"), std::string::npos);
}

TEST(ReadRecord, LongHeaderLinesAreALocatedErrorNotACrash) {
  // std::regex took 12 s on the first (20 kB of digits after "NPTS=") and overflowed the stack
  // on the second (200 kB of letters): now both are refused at their line at once.
  const std::string digits = RecordWithLine("digits.at2", "NPTS= " + std::string(20000, '9'));
  EXPECT_NE(ErrorOf(digits).find("digits.at2:2: a line of 20006 characters where the record's "
                                 "header is sought (header lines have at most 4096)"),
            std::string::npos)
      << ErrorOf(digits);
  const std::string letters = RecordWithLine("letters.at2", std::string(200000, 'a'));
  // Past every reader's line limit it is refused before the rest of the file is read.
  EXPECT_NE(ErrorOf(letters).find("letters.at2:2: a line of more than 65536 characters"),
            std::string::npos)
      << ErrorOf(letters);
  // Up to the bound a line is read: a 4000-character description changes nothing.
  const Record long_description =
      ReadRecord(RecordWithLine("description.at2", std::string(4000, '1') + " NPTS= 5"));
  EXPECT_EQ(long_description.values, (std::vector<double>{1.0, -2.0, 3.0}));
  EXPECT_DOUBLE_EQ(long_description.dt, 0.01);
}

TEST(ReadRecord, UnitsComeFromTheUnitsStatementOnly) {
  // "UNITS OF FT/S^2" is read as ft/s^2 although the description mentions "0.3 g"; 1 ft/s^2 is
  // 0.3048 m/s^2 exactly (the international foot).
  const Record feet = ReadRecord(DataFile("record_ft_beside_g.at2"));
  EXPECT_EQ(feet.units, "ft/s^2");
  EXPECT_EQ(feet.units_source, "header");
  EXPECT_DOUBLE_EQ(UnitSystem("N", "m", "s").Convert(1.0, feet.units, dimension::kAcceleration),
                   0.3048);
  // A statement naming no unit isolab knows is refused at its line, whatever else the header says.
  const std::string furlongs = ErrorOf(DataFile("bad_record_units_furlongs.at2"));
  EXPECT_NE(furlongs.find("bad_record_units_furlongs.at2:3: the units statement 'UNITS OF "
                          "FURLONGS' names no acceleration unit isolab knows"),
            std::string::npos)
      << furlongs;
  // A "g" in a description is no units statement: the units must be given, and then apply.
  EXPECT_NE(ErrorOf(DataFile("record_g_only_in_description.at2"))
                .find("the record's units are not in its header"),
            std::string::npos);
  const Record given =
      ReadRecord(DataFile("record_g_only_in_description.at2"), {"g", 0, "--units"});
  EXPECT_EQ(given.units, "g");
  EXPECT_EQ(given.units_source, "--units");
  // Given units that disagree with the statement are still refused.
  EXPECT_NE(ErrorOf(DataFile("record_ft_beside_g.at2"), {"g", 0, "--units"})
                .find("its header gives the units as ft/s^2 but --units gives g"),
            std::string::npos);
  // PEER's "CM/S/S" and a CSV value column's "(CM/SEC/SEC)" (not its time column's "(s)").
  const std::string bundled_gal = std::string(ISOLAB_TEST_DATA_DIR) + "/data/pulse_tp2_gal.at2";
  EXPECT_EQ(ReadRecord(bundled_gal).units, "cm/s^2");
  EXPECT_EQ(ReadRecord(DataFile("record_csv_time_and_units.csv")).units, "cm/s^2");
}

// A CSV record's time column in another unit than seconds is refused at its header: read as
// seconds, 10 ms samples made a 40 ms record 40 s long.
TEST(ReadRecord, CsvTimesInAnotherUnitThanSecondsAreRefused) {
  for (const char* unit : {"ms", "min", "mm"}) {
    const std::filesystem::path path = testing::OwnTestFile(std::string("times_") + unit + ".csv");
    std::ofstream(path) << "time (" << unit << "),acc (g)\n0,0\n10,0.1\n20,-0.1\n";
    const std::string error = ErrorOf(path.string());
    EXPECT_NE(error.find(path.filename().string() + ":1: the time column is in '" + unit +
                         "': a record's times must be in seconds"),
              std::string::npos)
        << error;
  }
  const std::filesystem::path seconds = testing::OwnTestFile("times_s.csv");
  std::ofstream(seconds) << "time (s),acc (g)\n0,0\n0.01,0.1\n0.02,-0.1\n";
  EXPECT_DOUBLE_EQ(ReadRecord(seconds.string()).dt, 0.01);
}

// A header's step of 0 or less is refused at its line: read as no step declared, a step given
// beside the file stood in for it silently.
TEST(ReadRecord, AHeaderStepThatIsNotPositiveIsALocatedError) {
  for (const char* step : {".0000", "-0.01"}) {
    const std::filesystem::path path = testing::OwnTestFile("step.at2");
    std::ofstream(path) << "PEER NGA STRONG MOTION DATABASE RECORD\nX\n"
                        << "ACCELERATION TIME SERIES IN UNITS OF G\n"
                        << "NPTS=      3, DT=   " << step << " SEC,\n  1.0  -2.0  3.0\n";
    for (const double given : {0.0, 0.01}) {
      const std::string error = ErrorOf(path.string(), {"", given, "", "--record-dt"});
      EXPECT_NE(error.find("step.at2:4: the header's sampling step DT = " + std::string(step) +
                           " must be > 0"),
                std::string::npos)
          << error;
    }
  }
}

TEST(ReadRecord, DeclaredCountBeyond64BitsIsALocatedError) {
  // It used to be read as -9223372036854775808 points.
  const std::string error = ErrorOf(DataFile("bad_record_npts_overflow.at2"));
  EXPECT_NE(error.find("bad_record_npts_overflow.at2:4: '99999999999999999999' points is out of "
                       "range"),
            std::string::npos)
      << error;
}

// A record in g, scaled by 2 into m/s^2 (g = 9.80665 m/s^2 by definition), its peak beside it; a
// scale that overflows a value is refused at the option that gave it, a unit the system cannot
// convert at the record's file.
TEST(ScaleRecord, ConvertsScalesAndRefusesWhatCannotBeScaled) {
  Record record;
  record.path = "r.at2";
  record.units = "g";
  record.dt = 0.01;
  record.values = {0.1, -0.3, 0.2};
  const UnitSystem si("N", "m");
  const ScaledRecord scaled = ScaleRecord(record, 2.0, si, "--scale");
  ASSERT_EQ(scaled.values.size(), 3u);
  EXPECT_DOUBLE_EQ(scaled.values[1], -0.3 * 2.0 * 9.80665);
  EXPECT_DOUBLE_EQ(scaled.pga, 0.3 * 2.0 * 9.80665);

  const auto error_of = [&](const Record& r, double scale) {
    try {
      ScaleRecord(r, scale, si, "scale");
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of(record, 1e308)
                .rfind("scale: 1e+308: the record r.at2 scaled by it is not a "
                       "finite number",
                       0),
            0u)
      << error_of(record, 1e308);
  // A model's scale is named at its line, by its key.
  try {
    RequireFiniteScaledRecord(std::vector<double>{1.0, HUGE_VAL}, 1e308, "r.at2", {"m.yaml", 7, 5},
                              "excitation.ground_motion: ");
    ADD_FAILURE() << "an infinite value passed";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what())
                  .rfind("m.yaml:7:5: excitation.ground_motion: scale 1e+308: "
                         "the record r.at2 scaled by it is not a finite number",
                         0),
              0u)
        << error.what();
  }
  Record furlongs = record;
  furlongs.units = "furlong/s^2";
  EXPECT_EQ(error_of(furlongs, 1.0).rfind("r.at2: units 'furlong/s^2': ", 0), 0u)
      << error_of(furlongs, 1.0);
}

}  // namespace
}  // namespace isolab::io
