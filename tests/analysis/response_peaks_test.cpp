// The peak tracker's building-wide floor acceleration and first-story shear, which it takes from
// the floors' and stories' own peaks once the rows are seen, and its stories' drifts and shears,
// which it reads off the displacements and force columns directly, against their definition
// written out here: each value of every row considered in turn, the first to exceed the largest
// kept, the drifts from the structure's MemberDeformation. Rows of values from a few levels, so
// that equal peaks at several floors, in one row and in later rows, are common; and rows made to
// tie.
#include "isolab/analysis/response_peaks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/model/model_file.h"

namespace isolab::analysis {
namespace {

// The bundled five-story building, on its isolators or (its first story then a spring from the
// ground) fixed at its base.
Problem FiveStories(bool fixed_base = false) {
  const model::ModelFile model = model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) +
                                                      "/models/buildings/five_story_table9.yaml");
  RunOverrides overrides;
  overrides.fixed_base = fixed_base;
  return Prepare(model, overrides);
}

// Rows of a problem's structure at rest but for the absolute accelerations and connection forces
// given (the spans must outlive the row).
class Rows {
 public:
  explicit Rows(const structure::Structure& structure)
      : structure_(structure),
        zeros_(std::max<std::size_t>(structure.dofs(),
                                     std::max(structure.law_count(), structure.force_columns())),
               0.0) {}

  integrators::ResponseRow Row(int step, double t, std::span<const double> acceleration,
                               std::span<const double> forces = {},
                               std::span<const double> displacement = {}) const {
    integrators::ResponseRow row;
    row.step = step;
    row.time = t;
    row.velocity = row.acceleration = Zeros(structure_.dofs());
    row.displacement = displacement.empty() ? Zeros(structure_.dofs()) : displacement;
    row.absolute_acceleration = acceleration;
    row.connection_force = forces.empty() ? Zeros(structure_.force_columns()) : forces;
    row.law_force = Zeros(structure_.law_count());
    return row;
  }

 private:
  std::span<const double> Zeros(std::size_t count) const { return {zeros_.data(), count}; }

  const structure::Structure& structure_;
  std::vector<double> zeros_;
};

// The definition: the first (row, floor) in order whose |value| exceeds the largest before it.
void ConsiderInTurn(Peak* peak, double value, double time, int index) {
  if (std::abs(value) > peak->value) *peak = {std::abs(value), time, index};
}

TEST(PeakTracker, FloorStoryAndFirstStoryPeaksAreTheFirstLargestOfEveryRowInTurn) {
  for (const bool fixed_base : {false, true}) {
    const Problem problem = FiveStories(fixed_base);
    const structure::Layout& layout = problem.layout;
    const structure::Structure& structure = problem.structure;
    ASSERT_EQ(layout.stories.size(), 5u);
    // The floors: every level but an isolated building's base.
    const std::size_t first_floor = layout.isolated() ? 1 : 0;
    ASSERT_EQ(layout.levels.size() - first_floor, 5u);
    const Rows rows(structure);
    for (const unsigned seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(::testing::Message()
                   << (fixed_base ? "fixed base" : "isolated") << ", seed " << seed);
      std::mt19937 random(seed);
      std::uniform_int_distribution<int> level(-3, 3);
      PeakTracker tracker(problem);
      Peak floor, first_story;
      std::vector<Peak> drifts(layout.stories.size()), shears(layout.stories.size());
      std::vector<double> acceleration(structure.dofs()), forces(structure.force_columns()),
          displacement(structure.dofs());
      for (int step = 0; step <= 200; ++step) {
        const double t = 0.01 * step;
        for (double& a : acceleration) a = level(random);
        for (double& f : forces) f = 10.0 * level(random);
        for (double& u : displacement) u = 0.1 * level(random);
        tracker.Observe(rows.Row(step, t, acceleration, forces, displacement));
        for (std::size_t s = 0; s < layout.stories.size(); ++s) {
          const int member = layout.stories[s].members[structure::kX];
          ConsiderInTurn(&drifts[s], structure.MemberDeformation(member, displacement), t,
                         static_cast<int>(s));
          ConsiderInTurn(&shears[s], forces[member], t, static_cast<int>(s));
        }
        for (std::size_t l = first_floor; l < layout.levels.size(); ++l) {
          ConsiderInTurn(&floor, acceleration[layout.levels[l].dofs[structure::kX]], t,
                         static_cast<int>(l));
        }
        ConsiderInTurn(&first_story, forces[layout.stories[0].members[structure::kX]], t, -1);
      }
      const ResponsePeaks peaks = tracker.Peaks();
      EXPECT_EQ(peaks.floor_acceleration.value, floor.value);
      EXPECT_EQ(peaks.floor_acceleration.time, floor.time);
      EXPECT_EQ(peaks.floor_acceleration.index, floor.index);
      EXPECT_EQ(peaks.first_story_shear.value, first_story.value);
      EXPECT_EQ(peaks.first_story_shear.time, first_story.time);
      EXPECT_EQ(peaks.first_story_shear.index, -1);
      for (std::size_t s = 0; s < layout.stories.size(); ++s) {
        SCOPED_TRACE(::testing::Message() << "story " << s);
        EXPECT_EQ(peaks.story_drifts[s].value, drifts[s].value);
        EXPECT_EQ(peaks.story_drifts[s].time, drifts[s].time);
        EXPECT_EQ(peaks.story_shears[s].value, shears[s].value);
        EXPECT_EQ(peaks.story_shears[s].time, shears[s].time);
      }
    }
  }
}

// The floor acceleration of rows, 0.01 s apart from 0.01 s, whose absolute accelerations are zero
// but at the floors given: (level, value) pairs.
Peak FloorAccelerationOf(const Problem& problem,
                         const std::vector<std::vector<std::pair<int, double>>>& values) {
  const Rows rows(problem.structure);
  PeakTracker tracker(problem);
  for (std::size_t r = 0; r < values.size(); ++r) {
    std::vector<double> acceleration(problem.structure.dofs(), 0.0);
    for (const auto& [level, value] : values[r]) {
      acceleration[problem.layout.levels[level].dofs[structure::kX]] = value;
    }
    tracker.Observe(rows.Row(static_cast<int>(r) + 1, 0.01 * (r + 1.0), acceleration));
  }
  return tracker.Peaks().floor_acceleration;
}

// Equal peaks: at two floors in one row the lower floor's; at a floor in a later row, the earlier
// row's, whether the later one is a lower floor or a higher one.
TEST(PeakTracker, OfEqualFloorAccelerationsTheEarliestRowsLowestFloorIsThePeak) {
  const Problem problem = FiveStories();
  const Peak same_row = FloorAccelerationOf(problem, {{{2, 3.0}, {4, -3.0}}, {{1, 3.0}}});
  EXPECT_EQ(same_row.value, 3.0);
  EXPECT_EQ(same_row.time, 0.01);
  EXPECT_EQ(same_row.index, 2);
  const Peak lower_later = FloorAccelerationOf(problem, {{{5, 5.0}}, {{3, -5.0}}, {{4, 5.0}}});
  EXPECT_EQ(lower_later.value, 5.0);
  EXPECT_EQ(lower_later.time, 0.01);
  EXPECT_EQ(lower_later.index, 5);
}

// At rest throughout, neither has a peak: zero, at time 0, at no floor.
TEST(PeakTracker, AtRestTheFloorAccelerationIsAtNoFloor) {
  const Problem problem = FiveStories();
  const Peak at_rest = FloorAccelerationOf(problem, {{}, {}, {}});
  EXPECT_EQ(at_rest.value, 0.0);
  EXPECT_EQ(at_rest.time, 0.0);
  EXPECT_EQ(at_rest.index, -1);
}

}  // namespace
}  // namespace isolab::analysis
