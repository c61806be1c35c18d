// Design files: the target, the suite and the checks read in the model's units, and every bad
// input refused at file:line:column with its key path and what was expected.
#include "isolab/model/design_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <variant>

#include "isolab/core/errors.h"
#include "own_test_file.h"

namespace isolab::model {
namespace {

namespace fs = std::filesystem;

const std::string kGroundMotions = std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/";

const std::string kOneDirection =
    std::string(ISOLAB_TEST_DATA_DIR) + "/study/data/two_story_lrb.yaml";

class DesignFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = testing::FreshTestDirectory();
    fs::copy_file(kOneDirection, directory_ / "building.yaml");
  }
  std::string Write(const std::string& text) {
    const fs::path path = directory_ / "design.yaml";
    std::ofstream(path) << text;
    return path.string();
  }
  // The message of the InputError that loading `text` throws.
  std::string ErrorOf(const std::string& text) {
    try {
      LoadDesignFile(Write(text));
    } catch (const InputError& error) {
      return error.what();
    }
    ADD_FAILURE() << text << "\nloaded without error";
    return {};
  }
  fs::path directory_;
};

::testing::AssertionResult Holds(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "'" << text << "' does not hold '" << part << "'";
}

const std::string kRecords = "suite:\n  records: [" + kGroundMotions + "fwn_firm_seed1.at2, " +
                             kGroundMotions + "fwn_soft_seed2.at2, " + kGroundMotions +
                             "elcentro_1940_ns.at2]\n";

TEST_F(DesignFileTest, ReadsTheTargetTheSuiteAndTheChecks) {
  const DesignFile design = LoadDesignFile(
      Write("model: building.yaml\ntarget: {asce7: {sms: 1.5 g, sm1: 8.826 m/s^2, tl: 6 s}}\n" +
            kRecords + "  period_range: [0.8, 1.2]\ndrift_limit: 0.02\n"));
  const auto* asce = std::get_if<spectra::Asce7Spectrum>(&design.target);
  ASSERT_NE(asce, nullptr);
  EXPECT_DOUBLE_EQ(asce->sms, 1.5);
  EXPECT_NEAR(asce->sm1, 8.826 / 9.80665, 1e-12);  // a quantity with its unit, in g
  EXPECT_DOUBLE_EQ(asce->long_period, 6.0);
  EXPECT_EQ(design.records.size(), 3u);
  EXPECT_FALSE(design.synthetic);
  EXPECT_DOUBLE_EQ(design.period_range[0], 0.8);
  EXPECT_DOUBLE_EQ(design.period_range[1], 1.2);
  EXPECT_DOUBLE_EQ(design.eccentricity, 0.0);  // one direction: no plan to shift in
  EXPECT_DOUBLE_EQ(design.drift_limit, 0.02);
}

TEST_F(DesignFileTest, ReadsEurocode8AndSyntheticSuites) {
  const DesignFile design = LoadDesignFile(
      Write("model: building.yaml\ntarget: {eurocode8: {agr: 0.3, ground: C, type: 2, "
            "importance: 1.2}}\nsuite: {synthetic: {count: 7, seed: 3, duration: 40 s}}\n"));
  const auto* ec8 = std::get_if<spectra::Eurocode8Spectrum>(&design.target);
  ASSERT_NE(ec8, nullptr);
  EXPECT_EQ(ec8->ground, spectra::GroundType::kC);
  EXPECT_EQ(ec8->type, 2);
  EXPECT_DOUBLE_EQ(ec8->importance, 1.2);
  ASSERT_TRUE(design.synthetic);
  EXPECT_EQ(design.synthetic->count, 7);
  EXPECT_EQ(design.synthetic->seed, 3u);
  EXPECT_DOUBLE_EQ(design.synthetic->duration, 40.0);
  // EN 1998-1's rules: its period range (3.2.3.1.2(4)c, T_1 the isolated period) and gamma_x.
  EXPECT_EQ(design.code, DesignCode::kEn1998_1);
  EXPECT_DOUBLE_EQ(design.period_range[0], 0.2);
  EXPECT_DOUBLE_EQ(design.period_range[1], 2.0);
  EXPECT_DOUBLE_EQ(design.gamma_x, 1.2);
  EXPECT_EQ(design.orientations, std::vector<double>{0.0});  // one direction
}

// A building in plan runs each pair H1 along x and then along y unless the file says otherwise;
// a building in one direction has no orientation to turn.
TEST_F(DesignFileTest, OrientationsOfThePairs) {
  const std::string plan =
      std::string(ISOLAB_SOURCE_DIR) + "/models/design/four_story_tfp_plan.yaml";
  const std::string head = "model: " + plan + "\ntarget: {asce7: {sms: 1.5, sm1: 0.9}}\n";
  const std::string suite = "suite:\n  synthetic: {count: 3}\n";
  EXPECT_EQ(LoadDesignFile(Write(head + suite)).orientations, (std::vector<double>{0.0, 90.0}));
  EXPECT_EQ(LoadDesignFile(Write(head + suite + "  orientations: [0, 45, 90]\n")).orientations,
            (std::vector<double>{0.0, 45.0, 90.0}));
  EXPECT_TRUE(Holds(ErrorOf(head + suite + "  orientations: [0, 0]\n"),
                    "design.yaml:5:21: suite.orientations[1]: 0 is given twice"));
  EXPECT_TRUE(Holds(ErrorOf(head + suite + "  orientations: [360]\n"),
                    "suite.orientations[0]: 360 (degrees in [0, 360))"));
  EXPECT_TRUE(Holds(ErrorOf(head + suite + "  orientations: []\n"),
                    "suite.orientations: expected a list of 1 to 8 angles"));
  EXPECT_TRUE(Holds(ErrorOf("model: building.yaml\ntarget: {asce7: {sms: 1.5, sm1: 0.9}}\n" +
                            kRecords + "  orientations: [0, 90]\n"),
                    "suite.orientations: '" + (directory_ / "building.yaml").string() +
                        "' moves in one direction"));
  EXPECT_TRUE(Holds(ErrorOf("model: building.yaml\ntarget: {asce7: {sms: 1.5, sm1: 0.9}}\n" +
                            kRecords + "gamma_x: 1.2\n"),
                    "gamma_x: is Eurocode 8's reliability factor"));
  // A record named as another turned by 90 degrees would share its run files.
  const std::string pair = "{h1: {file: " + kGroundMotions +
                           "fwn_firm_seed1.at2}, h2: {file: " + kGroundMotions +
                           "h2_fwn_firm_seed3.at2}";
  EXPECT_TRUE(Holds(ErrorOf(head + "suite:\n  records: [" + pair + ", name: a}, " + pair +
                            ", name: a_at90}, " + pair + ", name: b}]\n"),
                    "suite.records: 'a_at90' is also the name 'a' runs under turned by 90"));
}

TEST_F(DesignFileTest, RefusesWhatTheProcedureCannotDo) {
  const std::string head = "model: building.yaml\ntarget: {asce7: {sms: 1.5, sm1: 0.9}}\n";
  EXPECT_TRUE(Holds(ErrorOf(head + kRecords + "eccentricity: 0.05\n"),
                    "design.yaml:5:15: eccentricity: 0.05: accidental eccentricity shifts "
                    "floors in plan"));
  EXPECT_TRUE(Holds(ErrorOf(head + kRecords + "  period_range: [1.1, 1.25]\n"),
                    "suite.period_range: [1.1, 1.25] (0 < lower <= 1 <= upper"));
  EXPECT_TRUE(Holds(ErrorOf(head + "suite: {synthetic: {count: 2}}\n"),
                    "suite.synthetic.count: 2 (the response-history procedure needs at least 3"));
  EXPECT_TRUE(Holds(ErrorOf(head + "suite:\n  records: [" + kGroundMotions + "pulse_tp2.at2]\n"),
                    "suite.records: 1 (the response-history procedure needs at least 3"));
  EXPECT_TRUE(Holds(ErrorOf(head + "suite: {period_range: [0.75, 1.25]}\n"),
                    "suite: give records (files or pairs) or synthetic"));
  EXPECT_TRUE(Holds(ErrorOf(head + kRecords + "drift_limit: 1.5\n"), "drift_limit: 1.5 (a story"));
  EXPECT_TRUE(
      Holds(ErrorOf("model: building.yaml\ntarget: {asce7: {sms: -1.5, sm1: 0.9}}\n" + kRecords),
            "target.asce7.sms: -1.5 g (must be > 0)"));
  EXPECT_TRUE(Holds(
      ErrorOf("model: building.yaml\ntarget: {eurocode8: {agr: 0.3, ground: F}}\n" + kRecords),
      "target.eurocode8.ground: 'F' (A, B, C, D or E)"));
  EXPECT_TRUE(
      Holds(ErrorOf("model: building.yaml\ntarget: {asce7: {sms: 1.5, sm1: 0.9}, file: t.csv}\n" +
                    kRecords),
            "target: give one of asce7, eurocode8 or file"));
  EXPECT_TRUE(Holds(ErrorOf(head + "suite:\n  records: [" + kGroundMotions +
                            "pulse_tp2.at2, {file: " + kGroundMotions +
                            "fwn_firm_seed1.at2, scale: {pga: 0.4 g}}, " + kGroundMotions +
                            "fwn_soft_seed2.at2]\n"),
                    "the design scales its suite to the target spectrum"));
  std::ofstream(directory_ / "bare.yaml") << "units: {force: kN, length: mm, time: s}\n"
                                             "structure: {type: sdof, mass: 1}\n"
                                             "isolation: {components: [{name: k, type: "
                                             "linear_spring, k: 1}]}\n";
  EXPECT_TRUE(Holds(ErrorOf("model: bare.yaml\ntarget: {asce7: {sms: 1.5, sm1: 0.9}}\n" + kRecords),
                    "gives no property modification factors"));
}

}  // namespace
}  // namespace isolab::model
