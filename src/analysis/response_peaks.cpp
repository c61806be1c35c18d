#include "isolab/analysis/response_peaks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <variant>

#include "isolab/hysteresis/multiple_pendulum.h"

namespace isolab::analysis {
namespace {

using hysteresis::Norm;
using hysteresis::Vec2;
using structure::kGround;

void Consider(Peak* peak, double value, double time, int index = -1) {
  if (std::abs(value) > peak->value) *peak = {std::abs(value), time, index};
}

// A value with one or two horizontal components: |x| in one direction, the resultant in two.
double Magnitude(Vec2 v) { return v.y == 0.0 ? std::abs(v.x) : Norm(v); }

// A component's kernel as a law of elements in series, or nullptr (a bidirectional one's x law:
// its elements' states are read along x and y).
const hysteresis::SeriesArrangement* SeriesLawOf(const hysteresis::LawKernel& kernel) {
  return std::get_if<hysteresis::SeriesArrangement>(&kernel);
}
const hysteresis::SeriesArrangement* SeriesLawOf(const hysteresis::PlanLawKernel& kernel) {
  const auto* law = std::get_if<hysteresis::PlanSeriesArrangement>(&kernel);
  return law ? &law->law : nullptr;
}

// The largest of `peaks` (the first of equals), or an absent peak.
Peak Largest(const std::vector<Peak>& peaks) {
  Peak largest;
  for (const Peak& peak : peaks) {
    if (largest.index < 0 || peak.value > largest.value) largest = peak;
  }
  return largest;
}

// The largest of `peaks`, the earliest of equals, then the first of those; an absent peak where
// every one is zero. Rows come in time order, so this is the peak that considering each of their
// values at every row in turn would keep: the first to reach the largest.
Peak EarliestLargest(const std::vector<Peak>& peaks) {
  Peak largest;
  for (const Peak& peak : peaks) {
    if (peak.value > largest.value || (peak.value == largest.value && peak.time < largest.time)) {
      largest = peak;
    }
  }
  return largest;
}

}  // namespace

PeakTracker::PeakTracker(const Problem& problem) : problem_(problem) {
  const structure::Layout& layout = problem.layout;
  const std::size_t isolators = layout.isolators.size();
  for (std::size_t i = 0; i < isolators; ++i) {
    peaks_.isolator_displacements.push_back({0.0, 0.0, static_cast<int>(i)});
    peaks_.isolator_forces.push_back({0.0, 0.0, static_cast<int>(i)});
    peaks_.isolator_velocities.push_back({0.0, 0.0, static_cast<int>(i)});
  }
  for (std::size_t s = 0; s < layout.stories.size(); ++s) {
    peaks_.story_drifts.push_back({0.0, 0.0, static_cast<int>(s)});
    peaks_.story_shears.push_back({0.0, 0.0, static_cast<int>(s)});
  }
  if (layout.rotations) {
    for (std::size_t l = 0; l < layout.levels.size(); ++l) {
      peaks_.level_rotations.push_back({0.0, 0.0, static_cast<int>(l)});
    }
  }
  const bool base = layout.isolated() && !layout.stories.empty();
  for (std::size_t l = base ? 1 : 0; l < layout.levels.size(); ++l) {
    const std::array<int, 3>& dofs = layout.levels[l].dofs;
    floors_.push_back({static_cast<int>(l), dofs[structure::kX], dofs[structure::kY]});
    peaks_.floor_accelerations.push_back({0.0, 0.0, static_cast<int>(l)});
  }
  // Every step may be a row (Newmark): the window holds at most this many.
  const double dt = problem.grid.dt > 0.0 ? problem.grid.dt : 1.0;
  const auto capacity = static_cast<std::size_t>(std::floor(problem.residual_window / dt)) + 2;
  window_.assign(isolators, std::vector<Sample>(capacity));
  at_excitation_end_.assign(isolators, Vec2{});
  const std::size_t bearings = problem.structure.axial_loads().bearings.size();
  for (std::size_t j = 0; j < bearings; ++j) {
    peaks_.axial_load_minima.push_back(
        {std::numeric_limits<double>::infinity(), 0.0, static_cast<int>(j)});
    peaks_.axial_load_maxima.push_back(
        {-std::numeric_limits<double>::infinity(), 0.0, static_cast<int>(j)});
  }
  peaks_.uplift_durations.assign(bearings, 0.0);
  peaks_.first_uplift_times.assign(bearings, -1.0);
  peaks_.capacity_used.assign(isolators, {0.0, 0.0, 0.0, 0.0});
  peaks_.first_stop_times.assign(isolators, -1.0);
  peaks_.regimes_at_peak.assign(isolators, std::nullopt);
  at_peak_.assign(isolators, 0);
  const structure::Structure& s = problem.structure;
  for (const structure::StoryLayout& story : layout.stories) {
    story_terms_.push_back(DirectStoryTerms(s, story));
  }
  for (std::size_t i = 0; i < isolators; ++i) {
    const structure::IsolatorLayout& isolator = layout.isolators[i];
    const auto slot = static_cast<std::size_t>(isolator.slot);
    const std::size_t width = static_cast<std::size_t>(s.slot_width(slot));
    s.VisitSlotAssembly(slot, [&](const auto& assembly) {
      for (std::size_t c = 0; c < assembly.size(); ++c) {
        const hysteresis::SeriesArrangement* law = SeriesLawOf(assembly.kernels()[c]);
        if (law && hysteresis::LawAlongX(assembly.components()[c]).type() ==
                       hysteresis::LawType::kTripleFrictionPendulum) {
          triples_.push_back({i, law,
                              s.slot_law_offset(slot) + width * assembly.ElementStatesOffset(c),
                              width == 2});
        }
      }
    });
  }
}

// A story's terms read directly where its member is a spring along x between two dofs or from
// the ground: then |u[plus] - u[minus]| is |MemberDeformation|, to the bit (its terms are +1 and
// -1 times the two displacements, added in either order), and its shear the member's force.
PeakTracker::StoryTerms PeakTracker::DirectStoryTerms(const structure::Structure& structure,
                                                      const structure::StoryLayout& story) {
  StoryTerms terms;
  const int member = story.members[structure::kX];
  if (member < 0 || story.members[structure::kY] >= 0) return terms;
  const auto m = static_cast<std::size_t>(member);
  if (!structure.members()[m].IsBetween(&terms.minus, &terms.plus)) return terms;
  terms.column = static_cast<int>(structure.slot_force_column(m));
  return terms;
}

// Inlined into Observe's loop over the stories, where a call per story cost as much as the
// arithmetic (a tall building's rows).
[[gnu::always_inline]] inline Vec2 PeakTracker::StoryDrift(
    std::size_t story, const integrators::ResponseRow& row) const {
  const structure::StoryLayout& s = problem_.layout.stories[story];
  Vec2 drift;
  if (s.members[structure::kX] >= 0) {
    drift.x = problem_.structure.MemberDeformation(s.members[structure::kX], row.displacement);
  }
  if (s.members[structure::kY] >= 0) {
    drift.y = problem_.structure.MemberDeformation(s.members[structure::kY], row.displacement);
  }
  return drift;
}

[[gnu::always_inline]] inline Vec2 PeakTracker::StoryShear(
    std::size_t story, const integrators::ResponseRow& row) const {
  const structure::StoryLayout& s = problem_.layout.stories[story];
  Vec2 shear;
  if (s.members[structure::kX] >= 0) shear.x = row.connection_force[s.members[structure::kX]];
  if (s.members[structure::kY] >= 0) shear.y = row.connection_force[s.members[structure::kY]];
  return shear;
}

void PeakTracker::Observe(const integrators::ResponseRow& row) {
  const structure::Layout& layout = problem_.layout;
  const structure::Structure& structure = problem_.structure;
  const double t = row.time;
  ResponsePeaks& peaks = peaks_;

  // The residual window: drop the samples older than it, then add this row's.
  while (window_size_ > 0 && window_.front()[window_start_].t < t - problem_.residual_window) {
    window_start_ = (window_start_ + 1) % window_.front().size();
    --window_size_;
  }
  if (!window_.empty() && window_size_ == window_.front().size()) {
    window_start_ = (window_start_ + 1) % window_.front().size();
    --window_size_;
  }
  const bool before_end = t <= problem_.excitation_end * (1 + 1e-12);
  for (std::size_t i = 0; i < layout.isolators.size(); ++i) {
    const auto slot = static_cast<std::size_t>(layout.isolators[i].slot);
    const Vec2 u = structure.SlotDeformation(slot, row.displacement);
    const double largest = peaks.isolator_displacements[i].value;
    Consider(&peaks.isolator_displacements[i], Magnitude(u), t, static_cast<int>(i));
    at_peak_[i] = peaks.isolator_displacements[i].value > largest;
    Consider(&peaks.isolator_forces[i], Magnitude(structure.SlotForce(slot, row.connection_force)),
             t, static_cast<int>(i));
    // The deformation is linear in the dofs: the same map takes the velocities to its rate.
    Consider(&peaks.isolator_velocities[i],
             Magnitude(structure.SlotDeformation(slot, row.velocity)), t, static_cast<int>(i));
    std::vector<Sample>& ring = window_[i];
    ring[(window_start_ + window_size_) % ring.size()] = {t, u.x, u.y};
    if (before_end) at_excitation_end_[i] = u;
  }
  if (!window_.empty()) ++window_size_;

  Vec2 base_shear;
  for (const structure::GroundForce& term : layout.base_shear) {
    const Vec2 f = structure.SlotForce(term.slot, row.connection_force);
    if (structure.slot_width(term.slot) == 1) {
      (term.direction == structure::kX ? base_shear.x : base_shear.y) += f.x;
    } else {
      base_shear = base_shear + f;
    }
  }
  Consider(&peaks.base_shear, Magnitude(base_shear), t);

  const auto acceleration = [&](int x, int y) {
    return Magnitude(
        {row.absolute_acceleration[x], y == kGround ? 0.0 : row.absolute_acceleration[y]});
  };
  const int roof = static_cast<int>(layout.levels.size()) - 1;
  const std::array<int, 3>& roof_dofs = layout.roof().dofs;
  Consider(&peaks.roof_absolute_acceleration,
           acceleration(roof_dofs[structure::kX], roof_dofs[structure::kY]), t, roof);
  for (std::size_t f = 0; f < floors_.size(); ++f) {
    const Floor& floor = floors_[f];
    Consider(&peaks.floor_accelerations[f], acceleration(floor.x, floor.y), t, floor.level);
  }
  for (std::size_t s = 0; s < story_terms_.size(); ++s) {
    if (const StoryTerms& terms = story_terms_[s]; terms.column >= 0) {
      const double* u = row.displacement.data();
      const double drift = u[terms.plus] - (terms.minus == kGround ? 0.0 : u[terms.minus]);
      Consider(&peaks.story_shears[s], row.connection_force[terms.column], t, static_cast<int>(s));
      Consider(&peaks.story_drifts[s], drift, t, static_cast<int>(s));
      continue;
    }
    Consider(&peaks.story_shears[s], Magnitude(StoryShear(s, row)), t, static_cast<int>(s));
    Consider(&peaks.story_drifts[s], Magnitude(StoryDrift(s, row)), t, static_cast<int>(s));
  }
  if (layout.rotations) {
    for (std::size_t l = 0; l < layout.levels.size(); ++l) {
      Consider(&peaks.level_rotations[l],
               row.displacement[layout.levels[l].dofs[structure::kRotation]], t,
               static_cast<int>(l));
    }
    const structure::Level& base = layout.levels.front();
    Consider(&peaks.base_centre_displacement,
             Norm({row.displacement[base.dofs[structure::kX]],
                   row.displacement[base.dofs[structure::kY]]}),
             t, 0);
  }
  peaks.energies = row.energies;
  // A row without axial loads (a history read back) leaves them as they are.
  if (row.axial_load.size() == peaks.axial_load_minima.size()) {
    for (std::size_t j = 0; j < row.axial_load.size(); ++j) {
      const double n = row.axial_load[j];
      Peak& least = peaks.axial_load_minima[j];
      if (n < least.value) least = {n, t, static_cast<int>(j)};
      Peak& greatest = peaks.axial_load_maxima[j];
      if (n > greatest.value) greatest = {n, t, static_cast<int>(j)};
      if (n <= 0.0) {
        if (peaks.first_uplift_times[j] < 0.0) peaks.first_uplift_times[j] = t;
        if (peaks.rows > 0) peaks.uplift_durations[j] += t - last_time_;
      }
    }
  }
  last_time_ = t;
  if (!row.law_states.empty()) {
    for (const TriplePendulum& triple : triples_) {
      std::array<double, 4> used{};
      std::optional<hysteresis::PendulumRegime>& regime = peaks.regimes_at_peak[triple.isolator];
      const bool at_peak = at_peak_[triple.isolator] != 0;
      if (triple.plan) {
        std::array<hysteresis::PlanLawState, 4> elements;
        for (std::size_t k = 0; k < 4; ++k) {
          elements[k] = {row.law_states[triple.elements + 2 * k],
                         row.law_states[triple.elements + 2 * k + 1]};
        }
        used = hysteresis::TriplePendulumCapacityUsed(*triple.law, elements);
        if (at_peak) regime = hysteresis::TriplePendulumRegime(*triple.law, elements);
      } else {
        const auto elements = row.law_states.subspan(triple.elements, 4);
        used = hysteresis::TriplePendulumCapacityUsed(*triple.law, elements);
        if (at_peak) regime = hysteresis::TriplePendulumRegime(*triple.law, elements);
      }
      std::array<double, 4>& largest = peaks.capacity_used[triple.isolator];
      for (std::size_t k = 0; k < 4; ++k) {
        largest[k] = std::max(largest[k], used[k]);
        // At its restrainer the update puts a surface exactly at its capacity (to round-off).
        if (used[k] >= 1.0 - 1e-9 && peaks.first_stop_times[triple.isolator] < 0.0) {
          peaks.first_stop_times[triple.isolator] = t;
        }
      }
    }
  }
  ++peaks.rows;
}

ResponsePeaks PeakTracker::Peaks() const {
  const structure::Layout& layout = problem_.layout;
  ResponsePeaks peaks = peaks_;
  peaks.isolator_displacement = Largest(peaks.isolator_displacements);
  peaks.isolator_force = Largest(peaks.isolator_forces);
  peaks.isolator_velocity = Largest(peaks.isolator_velocities);
  peaks.story_drift = Largest(peaks.story_drifts);
  peaks.level_rotation = Largest(peaks.level_rotations);
  peaks.floor_acceleration = EarliestLargest(peaks.floor_accelerations);
  if (!peaks.story_shears.empty()) {
    peaks.first_story_shear = {peaks.story_shears[0].value, peaks.story_shears[0].time, -1};
  }
  if (peaks.story_drift.index >= 0) {
    const double height = layout.stories[peaks.story_drift.index].height;
    if (height > 0.0) peaks.story_drift_ratio = peaks.story_drift.value / height;
  }
  for (std::size_t s = 0; s < layout.stories.size(); ++s) {
    if (layout.stories[s].height > 0.0) {
      peaks.largest_drift_ratio = std::max(peaks.largest_drift_ratio,
                                           peaks.story_drifts[s].value / layout.stories[s].height);
    }
  }
  if (peaks.base_centre_displacement.value > 0.0) {
    peaks.torsional_amplification =
        peaks.isolator_displacement.value / peaks.base_centre_displacement.value;
  }
  for (std::size_t i = 0; i < window_.size(); ++i) {
    Vec2 low, high;
    for (std::size_t k = 0; k < window_size_; ++k) {
      const Sample& s = window_[i][(window_start_ + k) % window_[i].size()];
      low = k == 0 ? Vec2{s.x, s.y} : Vec2{std::min(low.x, s.x), std::min(low.y, s.y)};
      high = k == 0 ? Vec2{s.x, s.y} : Vec2{std::max(high.x, s.x), std::max(high.y, s.y)};
    }
    const Vec2 middle = 0.5 * (low + high), half = 0.5 * (high - low);
    const bool one_direction = problem_.structure.slot_width(layout.isolators[i].slot) == 1;
    peaks.isolator_residuals.push_back(one_direction ? middle.x : Norm(middle));
    peaks.isolator_oscillations.push_back(one_direction ? half.x : Norm(half));
    if (i == 0 ||
        std::abs(peaks.isolator_residuals[i]) > std::abs(peaks.residual_isolator_displacement)) {
      peaks.residual_isolator_displacement = peaks.isolator_residuals[i];
      peaks.residual_oscillation = peaks.isolator_oscillations[i];
    }
    const Vec2 end = at_excitation_end_[i];
    const double at_end = one_direction ? end.x : Norm(end);
    if (i == 0 || std::abs(at_end) > std::abs(peaks.isolator_displacement_at_excitation_end)) {
      peaks.isolator_displacement_at_excitation_end = at_end;
    }
  }
  return peaks;
}

ResponsePeaks ComputePeaks(const Problem& problem, const integrators::ResponseHistory& r) {
  PeakTracker tracker(problem);
  for (int row = 0; row < r.rows_written; ++row) tracker.Observe(r.Row(row));
  return tracker.Peaks();
}

}  // namespace isolab::analysis
