// Property modification factors (model/property_modification.h) and the bound models
// (model/bounds.h, `isolab bounds`): the factor arithmetic against hand calculations, the written
// upper-bound model's run against a model edited by hand, and bad factors as located errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
#include "isolab/core/errors.h"
#include "isolab/model/bounds.h"
#include "isolab/model/model_file.h"
#include "own_test_file.h"
#include "run_isolab.h"

namespace isolab::model {
namespace {

const std::string kRecord = std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/fwn_firm_seed1.at2";

std::string Write(const std::string& text, const std::string& name) {
  const std::string path = (testing::OwnTestDirectory() / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string Read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A two-story building on 16 lead-rubber bearings; `bearing` is the component's keys and
// `modification` the isolation's modification section (one line each).
std::string Model(const std::string& bearing, const std::string& modification) {
  return "units: {force: kN, length: mm, time: s}\n"  // 1
         "isolation:\n"                               // 2
         "  count: 16\n"                              // 3
         "  components: [{name: lrb, type: lead_rubber, " +
         bearing + "}]\n" +                                                        // 4
         (modification.empty() ? "" : "  modification: " + modification + "\n") +  // 5
         "structure: {type: shear_building, base_mass: 400 t,\n"
         "  stories: {count: 2, mass: 300 t, stiffness: 800 kN/mm}}\n"
         "excitation: {ground_motion: {file: " +
         kRecord +
         ", scale: 0.8}}\n"
         "analysis: {duration: 8}\n";
}

const std::string kFactors =
    "{lrb: {qd: {testing: [0.9, 1.15], ageing: [1.0, 1.2], specification: [0.85, 1.15]}, "
    "kd: {min: 0.9, max: 1.1}}}";

TEST(PropertyModification, CombinationIsAsce7Eq17_2_1And17_2_2) {
  // lambda_max = (1 + 0.75 (1.2 - 1)) 1.15 1.15 = 1.15 x 1.3225 = 1.520875;
  // lambda_min = (1 - 0.75 (1 - 1.0)) 0.9 0.85 = 0.765.
  const FactorPair a = CombineFactors({0.9, 1.15}, {1.0, 1.2}, {0.85, 1.15});
  EXPECT_NEAR(a.max, 1.520875, 1e-15);
  EXPECT_NEAR(a.min, 0.765, 1e-15);
  // An ageing minimum below 1 counts three quarters of its departure: (1 - 0.75 x 0.1) = 0.925;
  // 0.925 x 0.95 x 0.9 = 0.790875. The max: (1 + 0.75 x 0.4) x 1.1 x 1.05 = 1.3 x 1.155 = 1.5015.
  const FactorPair b = CombineFactors({0.95, 1.1}, {0.9, 1.4}, {0.9, 1.05});
  EXPECT_NEAR(b.min, 0.790875, 1e-15);
  EXPECT_NEAR(b.max, 1.5015, 1e-15);
  // No factors: the nominal value.
  const FactorPair none = CombineFactors({}, {}, {});
  EXPECT_EQ(none.min, 1.0);
  EXPECT_EQ(none.max, 1.0);
}

analysis::Summary RunModel(const ModelFile& model) {
  const analysis::Problem problem = analysis::Prepare(model, {});
  analysis::SolveOptions options;
  options.analysis = model.analysis;
  return analysis::Solve(options, problem);
}

TEST(PropertyModification, UpperModelRunsAsTheModelEditedByHand) {
  const std::string path = Write(Model("qd: 50, kd: \"1.0 kN/mm\", ku: 10", kFactors), "lrb.yaml");
  const ModelFile model = LoadModelFile(path);
  ASSERT_EQ(model.modifications.size(), 1u);
  const BoundModels bounds = MakeBoundModels(model);
  ASSERT_EQ(bounds.models.size(), 3u);
  ASSERT_EQ(bounds.properties.size(), 2u);
  EXPECT_EQ(bounds.properties[0].key, "qd");
  EXPECT_NEAR(bounds.properties[0].lambda.max, 1.520875, 1e-15);
  EXPECT_EQ(bounds.properties[1].upper, "1.1 kN/mm");  // the unit kept

  // By hand: qd = 50 x 1.520875 = 76.04375 kN, kd = 1.1 kN/mm (upper); qd = 50 x 0.765 = 38.25,
  // kd = 0.9 (lower).
  const ModelFile upper = LoadModelText(bounds.models[1].text, Write("", "upper.yaml"));
  const ModelFile upper_by_hand =
      LoadModelFile(Write(Model("qd: 76.04375, kd: 1.1, ku: 10", ""), "upper_by_hand.yaml"));
  const ModelFile lower = LoadModelText(bounds.models[2].text, Write("", "lower.yaml"));
  const ModelFile lower_by_hand =
      LoadModelFile(Write(Model("qd: 38.25, kd: 0.9, ku: 10", ""), "lower_by_hand.yaml"));
  EXPECT_TRUE(upper.modifications.empty());
  for (const auto& [bound, by_hand] :
       {std::pair{&upper, &upper_by_hand}, std::pair{&lower, &lower_by_hand}}) {
    const analysis::Summary a = RunModel(*bound);
    const analysis::Summary b = RunModel(*by_hand);
    ASSERT_TRUE(a.ok()) << a.run.message;
    ASSERT_TRUE(b.ok()) << b.run.message;
    // The written values are the hand's to the last digit: the runs are the same.
    EXPECT_EQ(a.peaks.isolator_displacement.value, b.peaks.isolator_displacement.value);
    EXPECT_EQ(a.peaks.base_shear.value, b.peaks.base_shear.value);
  }
  // The nominal model is the model as run.
  const analysis::Summary nominal = RunModel(LoadModelText(bounds.models[0].text, path));
  EXPECT_EQ(nominal.peaks.base_shear.value, RunModel(model).peaks.base_shear.value);
}

std::string ErrorOf(const std::string& text) {
  try {
    LoadModelFile(Write(text, "bad.yaml"));
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

TEST(PropertyModification, BadFactorsAreLocated) {
  const std::string bearing = "qd: 50, kd: 1.0, ku: 10";
  const std::string max_below = ErrorOf(Model(bearing, "{lrb: {qd: {testing: [0.9, 0.95]}}}"));
  EXPECT_NE(max_below.find("bad.yaml:5:44: isolation.modification.lrb.qd.testing: max = 0.95 "
                           "(a max factor must be >= 1"),
            std::string::npos)
      << max_below;
  const std::string min_above = ErrorOf(Model(bearing, "{lrb: {kd: {min: 1.1, max: 1.2}}}"));
  EXPECT_NE(min_above.find("bad.yaml:5:34: isolation.modification.lrb.kd.min: min = 1.1 (a min "
                           "factor must be > 0 and <= 1"),
            std::string::npos)
      << min_above;
  const std::string component = ErrorOf(Model(bearing, "{rubber: {kd: {min: 0.9, max: 1.2}}}"));
  EXPECT_NE(component.find("isolation.modification.rubber: no component is named 'rubber' (the "
                           "bearing's components: lrb)"),
            std::string::npos)
      << component;
  // A key the component gives that is not one of its law's parameters (a pendulum's period, from
  // which its radius follows) is neither scalable nor listed as one.
  const std::string period = ErrorOf(
      "units: {force: kN, length: mm, time: s}\nisolation:\n  components: [{name: fps, type: "
      "friction_pendulum, w: 1000, period: 3, mu: 0.05, uy: 0.5}]\n  modification: {fps: "
      "{period: {min: 0.9, max: 1.1}}}\nstructure: {type: sdof, mass: 100 t}\n");
  EXPECT_NE(period.find("'period' sets the pendulum's radius, its geometry, which property "
                        "modification factors do not vary (it gives: w, mu, uy)"),
            std::string::npos)
      << period;
  // A bound that breaks a law's rule is reported at the model given: the bound's own text is
  // never written, so no message names a file or line of it.
  std::string raised;
  try {
    MakeBoundModels(LoadModelFile(
        Write(Model("qd: 50, kd: 1.0, ku: 1.1", "{lrb: {kd: {min: 0.9, max: 1.2}}}"), "bad.yaml")));
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    raised = error.what();
  }
  EXPECT_NE(raised.find("bad.yaml: the upper bound model breaks a rule: "), std::string::npos)
      << raised;
  EXPECT_NE(raised.find("kd = 1.2"), std::string::npos) << raised;
  EXPECT_EQ(raised.find("bad_upper"), std::string::npos) << raised;
  const std::string key = ErrorOf(Model(bearing, "{lrb: {mu: {min: 0.9, max: 1.2}}}"));
  EXPECT_NE(key.find("isolation.modification.lrb.mu: 'mu' is not a parameter lrb gives (it "
                     "gives: qd, kd, ku)"),
            std::string::npos)
      << key;
}

TEST(BoundsCommand, WritesThreeModelsThatRunAlone) {
  const std::filesystem::path folder = testing::FreshTestDirectory();
  const std::string model = Write(Model("qd: 50, kd: 1.0, ku: 10", kFactors), "lrb.yaml");
  const std::filesystem::path elsewhere = folder / "elsewhere";
  std::filesystem::create_directories(elsewhere);
  // The output folder is made, as a design's is.
  const testing::Outcome outcome =
      testing::RunIsolab("bounds " + model + " -o " + (folder / "out").string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("1.521"), std::string::npos) << outcome.output;
  for (const char* bound : {"nominal", "upper", "lower"}) {
    const std::string written = (folder / "out" / (std::string("lrb_") + bound + ".yaml")).string();
    EXPECT_NE(Read(written).find("lead_rubber"), std::string::npos) << written;
    // From another folder (of the test's own: the run writes its results there): the record's
    // path was made absolute.
    const testing::Outcome run =
        testing::RunCommandLine("cd " + elsewhere.string() + " && " + std::string(ISOLAB_BINARY) +
                                " run " + written + " > /dev/null 2>&1");
    EXPECT_EQ(run.exit_code, 0) << written;
  }
  EXPECT_NE(Read((folder / "out" / "lrb_upper.yaml").string()).find("76.04375"), std::string::npos);

  const std::string plain = Write(Model("qd: 50, kd: 1.0, ku: 10", ""), "plain.yaml");
  const testing::Outcome refused =
      testing::RunIsolab("bounds " + plain + " -o " + (folder / "out").string(), true);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("no property modification factors"), std::string::npos)
      << refused.output;

  // Its own files it writes again; a file of someone else's at one of its names it refuses, and
  // leaves as it was.
  EXPECT_EQ(testing::RunIsolab("bounds " + model + " -q -o " + (folder / "out").string()).exit_code,
            0);
  const std::filesystem::path notes = folder / "out" / "lrb_lower.yaml";
  std::ofstream(notes) << "my notes\n";
  const testing::Outcome theirs =
      testing::RunIsolab("bounds " + model + " -q -o " + (folder / "out").string(), true);
  EXPECT_EQ(theirs.exit_code, 2) << theirs.output;
  EXPECT_NE(theirs.output.find("lrb_lower.yaml: exists, and isolab bounds did not write it"),
            std::string::npos)
      << theirs.output;
  EXPECT_EQ(Read(notes.string()), "my notes\n");
}

// The bundled plan model shares one pendulum among its four isolators through a YAML anchor
// (`components: &fp`, then `*fp`). Each isolator's modification scales its own copy once, as if
// the component were written out four times: mu 0.06 x 1.3 = 0.078 at the upper bound (not
// 0.06 x 1.3^4 = 0.171, which scaling the shared node through each alias gave), 0.06 x 0.8 =
// 0.048 at the lower.
TEST(BoundsCommand, AModificationReachedThroughAnAliasScalesOnce) {
  std::string text = Read(std::string(ISOLAB_SOURCE_DIR) + "/models/plan/five_story_fp_plan.yaml");
  const auto replace_all = [&text](const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size())) {
      text.replace(at, from.size(), to);
    }
  };
  replace_all("../../ground_motions/", std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/");
  const std::string modification = "modification: {fp: {mu: {min: 0.8, max: 1.3}}}";
  replace_all("components: *fp}", "components: *fp, " + modification + "}");
  replace_all("uy: 0.5}\n", "uy: 0.5}\n      " + modification + "\n");
  const ModelFile model = LoadModelFile(Write(text, "fp_plan_aliases.yaml"));
  ASSERT_EQ(model.modifications.size(), 4u);
  const BoundModels bounds = MakeBoundModels(model);
  ASSERT_EQ(bounds.properties.size(), 4u);
  for (const BoundProperty& p : bounds.properties) {
    EXPECT_EQ(p.upper, "0.078") << p.bearing;
    EXPECT_EQ(p.lower, "0.048") << p.bearing;
  }
  const auto count = [](const std::string& haystack, const std::string& needle) {
    int n = 0;
    for (std::size_t at = haystack.find(needle); at != std::string::npos;
         at = haystack.find(needle, at + 1)) {
      ++n;
    }
    return n;
  };
  EXPECT_EQ(count(bounds.models[0].text, "mu: 0.06"), 4) << bounds.models[0].text;
  EXPECT_EQ(count(bounds.models[1].text, "mu: 0.078"), 4) << bounds.models[1].text;
  EXPECT_EQ(count(bounds.models[2].text, "mu: 0.048"), 4) << bounds.models[2].text;
  // The written upper model reads back with each isolator's pendulum at 0.078.
  const ModelFile upper = LoadModelText(bounds.models[1].text, Write("", "fp_upper.yaml"));
  EXPECT_TRUE(upper.modifications.empty());
}

}  // namespace
}  // namespace isolab::model
