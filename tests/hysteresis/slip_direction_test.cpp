// The stick-or-slip decision against the rigid-plastic slider's definition: the yield function
// |q| - fs of a slider that slipped only grows while the motion goes on, and a reversal sticks
// until it has unloaded 2 fs.
#include "isolab/hysteresis/slip_direction.h"

#include <gtest/gtest.h>

#include <cmath>

namespace isolab::hysteresis {
namespace {

constexpr double kFs = 3.0, kStiffness = 2.0;

TEST(SlipDirection, ASlipGoesOnAtNoIncrementWhateverTheRoundOff) {
  // The stick force recomputed from a slipping state is fs up to round-off, on either side.
  for (const double recomputed : {std::nextafter(kFs, 0.0), kFs, std::nextafter(kFs, 10.0)}) {
    EXPECT_EQ(SlipDirection(+1, 0.0, recomputed, kStiffness, kFs), +1);
    EXPECT_EQ(SlipDirection(-1, 0.0, -recomputed, kStiffness, kFs), -1);
    EXPECT_EQ(SlipDirection(+1, 1e-3, recomputed, kStiffness, kFs), +1);
    EXPECT_EQ(SlipDirection(-1, -1e-3, -recomputed, kStiffness, kFs), -1);
  }
}

TEST(SlipDirection, AReversalSticksUntilItUnloadsTwiceFs) {
  const double full_unload = 2.0 * kFs / kStiffness;  // 3: q goes from +fs to -fs
  // Round-off above fs in the recomputed stick force must not make a reversal slip.
  const double recomputed = std::nextafter(kFs, 10.0);
  EXPECT_EQ(SlipDirection(+1, -1e-12, recomputed, kStiffness, kFs), 0);
  EXPECT_EQ(SlipDirection(+1, -0.999 * full_unload, recomputed, kStiffness, kFs), 0);
  EXPECT_EQ(SlipDirection(+1, -1.001 * full_unload, recomputed, kStiffness, kFs), -1);
  EXPECT_EQ(SlipDirection(-1, 0.999 * full_unload, -recomputed, kStiffness, kFs), 0);
  EXPECT_EQ(SlipDirection(-1, 1.001 * full_unload, -recomputed, kStiffness, kFs), +1);
}

TEST(SlipDirection, FromAStuckStateTheStickForceDecides) {
  EXPECT_EQ(SlipDirection(0, 0.5, 2.9, kStiffness, kFs), 0);
  EXPECT_EQ(SlipDirection(0, 0.5, 3.1, kStiffness, kFs), +1);
  EXPECT_EQ(SlipDirection(0, -0.5, -3.1, kStiffness, kFs), -1);
  EXPECT_EQ(SlipDirection(0, 0.0, kFs, kStiffness, kFs), 0);  // on the surface: not yet slipping
}

TEST(SlipDirection, WithoutAStickPhaseTheSliderAlwaysMovesWithTheForce) {
  EXPECT_EQ(SlipDirection(0, 0.0, 0.0, kStiffness, 0.0), +1);
  EXPECT_EQ(SlipDirection(0, -1e-9, -2e-9, kStiffness, 0.0), -1);
  EXPECT_EQ(SlipDirection(+1, -1e-9, 0.0, kStiffness, 0.0), -1);
  EXPECT_EQ(SlipDirection(-1, 0.0, 0.0, kStiffness, 0.0), -1);
}

}  // namespace
}  // namespace isolab::hysteresis
