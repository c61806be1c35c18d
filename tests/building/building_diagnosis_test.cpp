// The diagnosis of a building from its floor responses (building/building_diagnosis.h), on
// buildings isolab generates with a hidden isolation law and measures with noise on every
// channel: an isolation with a viscous part the model lacks must be named rate dependence, put
// back and borne out by the building's own fit; an isolation the model already describes must
// leave nothing named.
#include "isolab/building/building_diagnosis.h"

#include <gtest/gtest.h>

#include <random>

#include "isolab/core/errors.h"
#include "synthetic_building.h"

namespace isolab::building {
namespace {

using namespace synthetic;

// Every level's displacement and acceleration, with white noise of 0.1 % and 1 % of each
// channel's RMS: the loop's velocity is the displacement's difference over a sample, so the
// displacement's noise is what a displacement transducer gives, well below an accelerometer's.
std::vector<BuildingMotion> Measured(const model::ModelFile& truth) {
  std::vector<BuildingMotion> motions = {TableMotion("synthetic", 1500.0, 20.0)};
  Measure(truth, &motions);
  std::mt19937 random(11);
  for (Signal& x : motions[0].measured.displacement) AddNoise(&x, 0.001, &random);
  for (Signal& x : motions[0].measured.acceleration) AddNoise(&x, 0.01, &random);
  return motions;
}

BuildingFitSpec Spec() {
  BuildingFitSpec spec;
  for (const char* name : {"isolation.iso.k0", "isolation.iso.k1", "isolation.iso.uy",
                           "stories.stiffness", "damping.ratio"}) {
    spec.parameters.push_back({name});
  }
  return spec;
}

diagnosis::DiagnoseOptions Settings() {
  diagnosis::DiagnoseOptions options;
  options.budget = 3000;
  options.threads = 2;
  options.seed = 3;
  return options;
}

TEST(BuildingDiagnosis, NamesAViscousPartTheIsolationLacksAndTheBuildingBearsItOut) {
  const model::ModelFile truth = Model(
      BuildingText(std::string(kBilinear) + ", {name: visc, type: dashpot, c: 0.05}"));  // kN s/mm
  const std::vector<BuildingMotion> motions = Measured(truth);
  // The model lacks the dashpot; its bilinear law and superstructure start 20-30 % off.
  const model::ModelFile start =
      Model(BuildingText("{name: iso, type: bhm2, k0: 9.0, k1: 1.9, uy: 7.5}", 75.0, 0.03));
  const BuildingDiagnosis result =
      DiagnoseBuilding(start, motions, Spec(), Options(3000), Settings());

  ASSERT_FALSE(result.added.empty()) << result.isolator.stop_reason;
  EXPECT_EQ(result.isolator.steps.front().effect, diagnosis::Effect::kRateDependence);
  ASSERT_TRUE(result.refit.has_value());
  EXPECT_TRUE(result.confirmed) << result.conclusion;
  // The gap shrinks to the noise: every channel's NRMSE from well above 1 % to about 1 %.
  double worst_before = 0.0;
  for (std::size_t c = 0; c < result.refit->channels.size(); ++c) {
    SCOPED_TRACE(result.refit->channels[c].channel);
    worst_before = std::max(worst_before, result.base.channels[c].nrmse);
    EXPECT_LT(result.refit->channels[c].nrmse, 0.013);
  }
  EXPECT_GT(worst_before, 0.03);
  // The dashpot comes back: the added component's c within 10 % of the hidden 0.05 kN s/mm.
  const std::string c = "isolation." + result.added.front() + ".c";
  bool found = false;
  for (const FittedParameter& p : result.refit->parameters) {
    if (p.name != c) continue;
    found = true;
    EXPECT_NEAR(p.value / 0.05, 1.0, 0.1);
  }
  EXPECT_TRUE(found) << c;
  EXPECT_EQ(&result.Final(), &result.refit->fitted);
}

TEST(BuildingDiagnosis, NamesNothingWhenTheIsolationLacksNothing) {
  const std::vector<BuildingMotion> motions = Measured(Model(BuildingText(kBilinear)));
  const model::ModelFile start =
      Model(BuildingText("{name: iso, type: bhm2, k0: 9.0, k1: 1.9, uy: 7.5}", 75.0, 0.03));
  const BuildingDiagnosis result =
      DiagnoseBuilding(start, motions, Spec(), Options(3000), Settings());
  EXPECT_TRUE(result.added.empty()) << result.conclusion;
  EXPECT_FALSE(result.confirmed);
  EXPECT_EQ(&result.Final(), &result.base.fitted);
  for (const ChannelFit& channel : result.base.channels) EXPECT_LT(channel.nrmse, 0.013);
}

TEST(BuildingDiagnosis, RefusesMotionsWithoutEveryLevelsAcceleration) {
  std::vector<BuildingMotion> motions = Measured(Model(BuildingText(kBilinear)));
  motions[0].measured.acceleration[2].clear();
  BuildingFitSpec spec = Spec();
  spec.channels = {ParseChannel("d1", {"test"}), ParseChannel("a4", {"test"})};
  EXPECT_THROW(
      DiagnoseBuilding(Model(BuildingText(kBilinear)), motions, spec, Options(100), Settings()),
      InputError);
}

// The diagnosis refits every isolation component from the loops, so it cannot hold a prior given
// for one: refused before any fit, by the prior's name. A prior on the structure holds (here the
// loops name nothing, so the base fit is the final model).
TEST(BuildingDiagnosis, RefusesAPriorOnTheIsolationAndHoldsOneOnTheStructure) {
  const std::vector<BuildingMotion> motions = Measured(Model(BuildingText(kBilinear)));
  BuildingFitSpec spec = Spec();
  spec.parameters.pop_back();  // damping.ratio: given instead
  spec.priors = {{"isolation.iso.uy", 6.0, 0.1, "design data"}};
  try {
    DiagnoseBuilding(Model(BuildingText(kBilinear)), motions, spec, Options(100), Settings());
    ADD_FAILURE() << "accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("prior 'isolation.iso.uy': the building's diagnosis"),
              std::string::npos)
        << error.what();
  }
  spec.priors = {{"damping.ratio", 0.04, 0.2, "design data"}};
  const BuildingDiagnosis result = DiagnoseBuilding(Model(BuildingText(kBilinear, 60.0, 0.03)),
                                                    motions, spec, Options(600), Settings());
  EXPECT_EQ(analysis::ParameterValue(result.base.fitted, "damping.ratio"), 0.04);
  EXPECT_EQ(analysis::ParameterValue(result.Final(), "damping.ratio"), 0.04);
}

}  // namespace
}  // namespace isolab::building
