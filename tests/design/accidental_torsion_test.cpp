// Accidental eccentricity against the statics of a rigid slab. A slab of mass m on four equal
// bearings of stiffness k at the corners of an L_x x L_y plan, its centre of mass moved by e_y
// across a ground acceleration a along x, held long enough to come to rest: the inertial force
// F = m a acts at the shifted centre, so the slab translates F / (4 k) and turns
// theta = F e_y / k_theta, k_theta = 4 k ((L_x/2)^2 + (L_y/2)^2), and a corner moves
// (F / (4 k) + theta L_y / 2, theta L_x / 2).
#include "isolab/design/accidental_torsion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
#include "isolab/core/errors.h"
#include "isolab/model/model_file.h"
#include "own_test_file.h"

namespace isolab::design {
namespace {

using analysis::Prepare;
using analysis::Problem;
using analysis::Solve;
using analysis::Summary;

using testing::OwnTestDirectory;
using testing::OwnTestFile;

constexpr double kLx = 30000, kLy = 20000;  // mm
constexpr double kStiffness = 1.0;          // kN/mm per bearing
constexpr double kMass = 0.4;               // kN s^2/mm (400 t)
constexpr double kAcceleration = 0.1;       // g

// 0.1 g along x reached by a half-cosine over 40 s, then held 40 s: the slab ends at rest.
std::string WriteRamp() {
  const auto path = OwnTestFile("ramp.txt");
  std::ofstream file(path);
  for (int k = 0; k <= 8000; ++k) {
    const double t = 0.01 * k;
    const double a =
        t < 40 ? kAcceleration * 0.5 * (1 - std::cos(std::numbers::pi * t / 40)) : kAcceleration;
    file << t << " " << a << "\n";
  }
  return path.string();
}

model::ModelFile Slab(const std::string& record) {
  // Dashpots damp translation at 70 % of critical and torsion more, so the end is static.
  const std::string text = R"(units: {force: kN, length: mm, time: s}
plan:
  footprint: [[0, 0], [30000, 20000]]
  base: {mass: 400 t}
  isolators:
    - name: corner
      positions: [[0, 0], [30000, 0], [0, 20000], [30000, 20000]]
      components: [{name: k, type: linear_spring, k: 1.0}, {name: c, type: dashpot, c: 0.443}]
excitation:
  ground_motion: {file: )" +
                           record + R"(, units: g}
analysis: {dt: 0.01, free_vibration: 0}
)";
  return model::LoadModelText(text, (OwnTestDirectory() / "slab.yaml").string());
}

TEST(AccidentalEccentricity, IsFivePercentOfThePlanEachWayInFourCases) {
  const model::ModelFile slab = Slab(WriteRamp());
  const std::vector<EccentricityCase> cases = AccidentalEccentricities(slab, 0.05, "eccentricity");
  ASSERT_EQ(cases.size(), 4u);
  EXPECT_EQ(cases[0].name, "ex+ey+");
  EXPECT_DOUBLE_EQ(cases[0].shift.x, 1500.0);
  EXPECT_DOUBLE_EQ(cases[0].shift.y, 1000.0);
  EXPECT_EQ(cases[3].name, "ex-ey-");
  EXPECT_DOUBLE_EQ(cases[3].shift.x, -1500.0);
  EXPECT_DOUBLE_EQ(cases[3].shift.y, -1000.0);
}

TEST(AccidentalEccentricity, TurnsTheSlabAsItsStaticsSay) {
  const std::string record = WriteRamp();
  const model::ModelFile slab = Slab(record);
  const double e = 0.05 * kLy;
  const Problem problem = Prepare(WithCentresOfMassShifted(slab, {0.0, e}), {});
  const Summary summary = Solve({}, problem);
  ASSERT_TRUE(summary.ok());

  const double force = kMass * kAcceleration * 9806.65;
  const double theta = force * e / (kStiffness * (kLx * kLx + kLy * kLy));
  const double along = force / (4 * kStiffness) + theta * kLy / 2;
  const double across = theta * kLx / 2;
  const double corner = std::hypot(along, across);
  EXPECT_NEAR(summary.peaks.isolator_displacement.value, corner, 1e-3 * corner);
  // Without the shift the slab only translates: the eccentricity is what turned it.
  const Summary centred = Solve({}, Prepare(slab, {}));
  EXPECT_NEAR(centred.peaks.isolator_displacement.value, force / (4 * kStiffness),
              1e-3 * force / (4 * kStiffness));
  EXPECT_GT(corner / (force / (4 * kStiffness)), 1.02);
}

TEST(AccidentalEccentricity, IsRefusedForABuildingInOneDirection) {
  const model::ModelFile sdof = model::LoadModelText(
      "units: {force: kN, length: mm, time: s}\nstructure: {type: sdof, mass: 1}\n"
      "isolation:\n  components: [{name: k, type: linear_spring, k: 1}]\n",
      "sdof.yaml");
  try {
    AccidentalEccentricities(sdof, 0.05, "eccentricity");
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("eccentricity"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("not a building in plan"), std::string::npos);
  }
}

}  // namespace
}  // namespace isolab::design
