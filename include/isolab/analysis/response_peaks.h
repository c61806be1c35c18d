// The peaks an engineer reads first from a run, for any structure (layout.h): each isolator's
// displacement and force, base shear, story drifts and shears, the roof's and the floors'
// absolute acceleration, the levels' rotations (in plan) and how much the base's twist adds at the
// worst isolator; and where the isolators come to rest. A quantity with two horizontal components
// (in plan) peaks as the resultant |(x, y)|; in one direction, as |x|.
//
// The residual isolator displacement is read after the free vibration that follows the
// excitation (problem.h): the middle of the isolator's range over the last `residual_window` of
// the run. A structure at rest gives its final displacement; a bearing that still swings
// elastically about an offset (a bilinear isolator below yield is undamped) gives that offset, and
// half the range says how much it still swings.
//
// A PeakTracker sees every step of a run (it is a ResponseObserver), whatever the results file
// keeps, and holds no history: only the isolators' displacements within the residual window, in
// buffers sized before the run.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/hysteresis/multiple_pendulum.h"
#include "isolab/integrators/response.h"

namespace isolab::analysis {

struct Peak {
  double value = 0.0;  // largest absolute value (or resultant)
  double time = 0.0;
  int index = -1;  // the isolator, story or level where it occurred; -1: none
};

struct ResponsePeaks {
  // Per isolator (the layout's order): the peak of |u| and of |f|.
  std::vector<Peak> isolator_displacements, isolator_forces;
  // The largest of them (index: the isolator); absent (index -1) without isolators.
  Peak isolator_displacement, isolator_force;
  // Per isolator, the peak of |du/dt| (the resultant in plan), and the largest: what a run is
  // compared with the range its isolation was identified on (model::ModelFile::identified_range).
  std::vector<Peak> isolator_velocities;
  Peak isolator_velocity;
  Peak base_shear;                  // the force into the ground
  Peak first_story_shear;           // the lowest story's (absent without stories)
  std::vector<Peak> story_shears;   // per story: the peak of its shear (x, y resultant in plan)
  Peak roof_absolute_acceleration;  // the top level's
  // The largest absolute acceleration of the floors above the isolators (every level of a
  // structure without stories); index: the level.
  Peak floor_acceleration;
  std::vector<Peak> floor_accelerations;  // each of those floors' (index: the level)
  std::vector<Peak> story_drifts;         // per story: its drift at its centre of stiffness
  Peak story_drift;                       // the largest (index: the story)
  double story_drift_ratio = 0.0;         // that drift / its story's height (0 without a height)
  // The largest peak drift / height over the stories with a height (not necessarily the largest
  // drift's story); 0 when no story has a height.
  double largest_drift_ratio = 0.0;
  // Rotating levels only (empty, zero otherwise): each level's peak |rotation| (rad), the
  // largest (index: the level), the base's centre of mass's peak displacement, and the largest
  // isolator displacement over it (the twist's amplification).
  std::vector<Peak> level_rotations;
  Peak level_rotation;
  Peak base_centre_displacement;
  double torsional_amplification = 0.0;
  // Per isolator, the middle of its range over the residual window (signed along x in one
  // direction, the resultant in plan) and half that range; the headline values are the isolator's
  // with the largest |residual|, and the largest |u| at the end of the excitation.
  std::vector<double> isolator_residuals, isolator_oscillations;
  double residual_isolator_displacement = 0.0;
  double residual_oscillation = 0.0;
  double isolator_displacement_at_excitation_end = 0.0;
  // Per bearing of the structure's axial loads (structure/axial_load.h; empty without them): the
  // least axial load N (signed; its time; index: the bearing), the time spent at N <= 0 (uplift:
  // the bearing carries no shear) summed over the rows, and when uplift first happened (-1: never).
  std::vector<Peak> axial_load_minima;
  std::vector<Peak> axial_load_maxima;  // the greatest axial load N of each
  std::vector<double> uplift_durations, first_uplift_times;
  // Per isolator: the largest fraction of its displacement capacity a triple friction pendulum's
  // surfaces used (|u_i| / d_i, surfaces 1 to 4; multiple_pendulum.h), all zero for an isolator
  // without one, and when a surface first reached its restrainer (|u_i| = d_i; -1: never).
  std::vector<std::array<double, 4>> capacity_used;
  std::vector<double> first_stop_times;
  // Per isolator: the regime of its triple friction pendulum at the row of the isolator's peak
  // displacement (multiple_pendulum.h: the regime of the state's last increment, so the one the
  // peak was reached in), from the laws' states that Newmark's rows carry; empty for an isolator
  // without one, or where the rows carry no states (IDA).
  std::vector<std::optional<hysteresis::PendulumRegime>> regimes_at_peak;
  integrators::Energies energies;  // at the last row seen (zero before any)
  int rows = 0;                    // rows seen
};

class PeakTracker final : public integrators::ResponseObserver {
 public:
  // Every buffer is sized here, for the problem's grid.
  explicit PeakTracker(const Problem& problem);
  void Observe(const integrators::ResponseRow& row) override;
  // The peaks of the rows seen so far.
  ResponsePeaks Peaks() const;

 private:
  // A story's drift and shear (x, y; y = 0 in one direction) at a row.
  hysteresis::Vec2 StoryDrift(std::size_t story, const integrators::ResponseRow& row) const;
  hysteresis::Vec2 StoryShear(std::size_t story, const integrators::ResponseRow& row) const;

  const Problem& problem_;
  ResponsePeaks peaks_;
  // The levels whose acceleration is a floor's, with their dofs along x and y.
  struct Floor {
    int level = 0, x = structure::kGround, y = structure::kGround;
  };
  std::vector<Floor> floors_;
  // Per story: where its member is a spring along x between two dofs (or from the ground), its
  // force column and the dofs its drift u[plus] - u[minus] takes (minus kGround: the ground), read
  // directly; column < 0 for any other story, which StoryDrift and StoryShear take.
  struct StoryTerms {
    int column = -1, plus = structure::kGround, minus = structure::kGround;
  };
  std::vector<StoryTerms> story_terms_;
  static StoryTerms DirectStoryTerms(const structure::Structure& structure,
                                     const structure::StoryLayout& story);
  // Per isolator, a ring of (time, u_x, u_y) over the last residual window.
  struct Sample {
    double t, x, y;
  };
  std::vector<std::vector<Sample>> window_;
  std::size_t window_start_ = 0, window_size_ = 0;
  std::vector<hysteresis::Vec2> at_excitation_end_;
  double last_time_ = 0.0;  // of the previous row
  // The triple pendulums among the isolators' components: the isolator, the law, and where its
  // elements' states start in the structure's state array (LawState pairs in plan).
  struct TriplePendulum {
    std::size_t isolator = 0;
    const hysteresis::SeriesArrangement* law = nullptr;
    std::size_t elements = 0;
    bool plan = false;
  };
  std::vector<TriplePendulum> triples_;
  // Per isolator, whether the row being observed is its peak displacement so far.
  std::vector<char> at_peak_;
};

// The peaks of a history's rows (a PeakTracker fed with them).
ResponsePeaks ComputePeaks(const Problem& problem, const integrators::ResponseHistory& response);

}  // namespace isolab::analysis
