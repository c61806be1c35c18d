// A law driven through displacements with its whole state block (law_kernel.h: StateSlots
// LawStates), for the tests of sliders in series: trials from the committed block, commits by
// copying.
#pragma once

#include <vector>

#include "isolab/hysteresis/law_kernel.h"

namespace isolab::hysteresis::testing {

struct BlockStep {
  std::vector<LawState> state;
  LawResponse response;
  const LawState& main() const { return state[0]; }
};

class DrivenLaw {
 public:
  explicit DrivenLaw(LawKernel kernel)
      : kernel_(std::move(kernel)), committed_(StateSlots(kernel_)) {}

  BlockStep Trial(double u) const { return TrialFrom(committed_, u); }
  BlockStep TrialFrom(const std::vector<LawState>& from, double u) const {
    BlockStep step{std::vector<LawState>(from.size()), {}};
    UpdateLaw(kernel_, from, {u, 0.0, 0.0}, step.state, &step.response);
    return step;
  }
  // Moves to u and commits; returns the step.
  BlockStep MoveTo(double u) {
    BlockStep step = Trial(u);
    committed_ = step.state;
    return step;
  }

  const LawKernel& kernel() const { return kernel_; }
  const std::vector<LawState>& committed() const { return committed_; }
  void set_committed(std::vector<LawState> state) { committed_ = std::move(state); }
  double force() const { return committed_[0].force; }
  double StoredEnergy() const { return hysteresis::StoredEnergy(kernel_, committed_); }

 private:
  LawKernel kernel_;
  std::vector<LawState> committed_;
};

}  // namespace isolab::hysteresis::testing
