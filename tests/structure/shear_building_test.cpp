#include "isolab/structure/shear_building.h"

#include <gtest/gtest.h>

#include "isolab/hysteresis/law_parameters.h"

namespace isolab::structure {
namespace {

using hysteresis::LawType;
using hysteresis::ParallelAssembly;

ParallelAssembly Linear(double k) { return hysteresis::SingleLaw(LawType::kLinearSpring, {k}); }

std::vector<Story> ChopraFiveStory() {
  std::vector<Story> stories;
  for (int i = 0; i < 5; ++i) stories.push_back({"story", 100.0 / 386.4, 144.0, Linear(31.54)});
  return stories;
}

TEST(FixedBaseModes, ChopraCaseEPeriodsAndEffectiveMasses) {
  const Modes modes = FixedBaseModes(ChopraFiveStory());
  const double periods[] = {2.0000, 0.6850, 0.4346, 0.3383, 0.2966};
  const double masses[] = {0.8795, 0.0872, 0.0242, 0.0075, 0.0016};
  for (int n = 0; n < 5; ++n) {
    EXPECT_NEAR(modes.periods[n] / periods[n], 1.0, 1e-3) << "mode " << n + 1;
    EXPECT_NEAR(modes.effective_mass_ratios[n], masses[n], 1e-4) << "mode " << n + 1;
  }
}

TEST(ShearBuilding, ModalDampingGivesEachModeItsRatio) {
  ShearBuilding building;
  building.stories = ChopraFiveStory();
  building.damping.kind = SuperstructureDamping::Kind::kModal;
  building.damping.modal_ratios = {0.05};
  const Structure structure = BuildShearBuilding(building).structure;
  const Modes modes = FixedBaseModes(building.stories);
  const Eigen::MatrixXd c = Eigen::MatrixXd(structure.viscous_damping());
  const Eigen::MatrixXd modal = modes.shapes.transpose() * c * modes.shapes;
  for (int n = 0; n < 5; ++n) {
    EXPECT_NEAR(modal(n, n), 2 * 0.05 * modes.circular_frequencies[n], 1e-9);
    for (int m = 0; m < 5; ++m) {
      if (m != n) {
        EXPECT_NEAR(modal(n, m), 0.0, 1e-9);
      }
    }
  }
}

TEST(ShearBuilding, RayleighDampingGivesTheChosenModesTheirRatios) {
  // An irregular building, modes 1 and 3 matched: the frequencies come from bisection, the check
  // from the dense modal basis.
  ShearBuilding building;
  for (int i = 0; i < 8; ++i) {
    building.stories.push_back({"story", 0.02 + 0.003 * (i % 3), 3000.0, Linear(90.0 - 7.0 * i)});
  }
  building.damping.kind = SuperstructureDamping::Kind::kRayleigh;
  building.damping.rayleigh_modes[1] = 3;
  building.damping.rayleigh_ratios[0] = 0.02;
  building.damping.rayleigh_ratios[1] = 0.05;
  const Structure structure = BuildShearBuilding(building).structure;
  const Modes modes = FixedBaseModes(building.stories);
  const Eigen::MatrixXd c = Eigen::MatrixXd(structure.viscous_damping());
  const Eigen::MatrixXd modal = modes.shapes.transpose() * c * modes.shapes;
  EXPECT_NEAR(modal(0, 0) / (2 * modes.circular_frequencies[0]), 0.02, 1e-12);
  EXPECT_NEAR(modal(2, 2) / (2 * modes.circular_frequencies[2]), 0.05, 1e-12);
  EXPECT_NEAR(modal(0, 2), 0.0, 1e-12 * modal(2, 2));  // classical damping: no coupling
}

TEST(ShearBuilding, IsolatedDampingLeavesRigidBodyMotionUndamped) {
  ShearBuilding building;
  building.stories = ChopraFiveStory();
  building.isolated = true;
  building.base_mass = 100.0 / 386.4;
  building.isolation = Linear(3.0);
  building.damping.kind = SuperstructureDamping::Kind::kRayleigh;
  building.damping.rayleigh_ratios[0] = building.damping.rayleigh_ratios[1] = 0.05;
  const Structure structure = BuildShearBuilding(building).structure;
  EXPECT_EQ(structure.dofs(), 6);
  const Eigen::VectorXd rigid = Eigen::VectorXd::Ones(6);
  EXPECT_NEAR((structure.viscous_damping() * rigid).norm(), 0.0, 1e-12);
  EXPECT_EQ(structure.MemberDeformation(0, std::vector<double>{2.0, 5.0}), 2.0);  // grounded
  EXPECT_EQ(structure.MemberDeformation(1, std::vector<double>{2.0, 5.0}), 3.0);  // on the base
}

}  // namespace
}  // namespace isolab::structure
