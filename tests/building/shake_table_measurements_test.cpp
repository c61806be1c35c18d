// A building's shake-table measurements: the levels ordered slab to roof by how much they move
// (auto) or as named, the accelerometers' offsets read from the quiet start and removed (or kept
// with offsets none), and a level list that names a channel twice or the wrong count refused, as
// is a model whose level count is not the file's under auto.
#include "isolab/building/shake_table_measurements.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "isolab/core/errors.h"
#include "own_test_file.h"

namespace isolab::building {
namespace {

// Two levels, channel 1 the roof (moving twice as much as the slab, channel 2), 20 quiet samples
// then a sine on the table; both accelerometers read 0.3 m/s^2 too much throughout.
std::string WriteTwoLevels() {
  const auto path = isolab::testing::OwnTestDirectory() / "two_levels.csv";
  std::ofstream out(path);
  out.precision(17);
  out << "time_s,table_acceleration_m_s2,table_displacement_m,a1_m_s2,a2_m_s2,d1_m,d2_m\n";
  for (int k = 0; k < 60; ++k) {
    const double t = 0.01 * k, s = k < 20 ? 0.0 : std::sin(0.5 * (k - 20));
    out << t << "," << s << ",0," << 0.3 + 2 * s << "," << 0.3 + s << "," << 0.02 * s << ","
        << 0.01 * s << "\n";
  }
  return path.string();
}

const UnitSystem kSi("kN", "m", "s");

TEST(ShakeTableMeasurements, OrdersTheLevelsByMotionAndRemovesThePreEventOffsets) {
  ShakeTableChannels channels;
  channels.displacements = "relative";
  const LevelMeasurements m = ReadShakeTableMeasurements(WriteTwoLevels(), channels, kSi, 2);
  EXPECT_EQ(m.channels, (std::vector<int>{2, 1}));  // the slab moves least
  ASSERT_EQ(m.acceleration.size(), 2u);
  EXPECT_NEAR(m.acceleration[0][0], 0.0, 1e-12);  // the offset is gone
  EXPECT_NEAR(m.acceleration[1][30], 2 * std::sin(5.0), 1e-9);
  EXPECT_NEAR(m.displacement[1][30], 0.02 * std::sin(5.0), 1e-12);
  EXPECT_EQ(m.reference_note, "displacements relative to the table (as given)");

  channels.offsets = "none";
  channels.levels = "1,2";
  const LevelMeasurements kept = ReadShakeTableMeasurements(WriteTwoLevels(), channels, kSi, 2);
  EXPECT_EQ(kept.channels, (std::vector<int>{1, 2}));
  EXPECT_NEAR(kept.acceleration[0][0], 0.3, 1e-12);
}

TEST(ShakeTableMeasurements, RefusesALevelListThatDoesNotFitTheModel) {
  ShakeTableChannels channels;
  for (const auto& [levels, message] :
       {std::pair{"1,1", "--levels 1,1: channel 1 is given twice (levels 1 and 2)"},
        std::pair{"1,x", "--levels 1,x: 'x' is not a channel number"},
        std::pair{"1", "--levels names 1 channels; the model has 2 levels"}}) {
    channels.levels = levels;
    try {
      ReadShakeTableMeasurements(WriteTwoLevels(), channels, kSi, 2);
      ADD_FAILURE() << levels;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(message), std::string::npos) << error.what();
    }
  }
}

// With --levels auto the model's levels must be the file's: an SDOF or a one-floor model read
// only channel 1, the roof here, as its slab, and dropped the rest without a word.
TEST(ShakeTableMeasurements, AutoLevelsRefuseAModelWithOtherThanTheFilesLevelCount) {
  const ShakeTableChannels channels;  // levels auto
  for (const auto& [levels, message] :
       {std::pair{std::size_t{1},
                  "the file has 2 level channels (a1 to a2) and the model 1 level "
                  "(an SDOF's mass)"},
        std::pair{std::size_t{3},
                  "the file has 2 level channels (a1 to a2) and the model 3 "
                  "levels (the isolation slab and 2 floors)"}}) {
    try {
      ReadShakeTableMeasurements(WriteTwoLevels(), channels, kSi, levels);
      ADD_FAILURE() << levels;
    } catch (const InputError& error) {
      EXPECT_NE(
          std::string(error.what()).find("two_levels.csv: --levels auto: " + std::string(message)),
          std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace isolab::building
