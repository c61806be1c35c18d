// A record scaled to a target (excitation.ground_motion.scale: {pga: ...} or {sa: ..., period:
// ...}): the applied record reaches the target, measured independently of the code that computed
// the factor (the file's own samples for PGA, the spectrum re-run on the scaled record for Sa, a
// sine whose PGA is its amplitude), one factor scales a whole pair, and bad targets are refused
// where they are written.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "brute_force_spectrum.h"
#include "isolab/analysis/problem.h"
#include "isolab/core/errors.h"
#include "isolab/model/model_file.h"

namespace isolab::analysis {
namespace {

constexpr double kG = 9806.65;  // standard gravity in mm/s^2, the models' acceleration unit here

const std::string kSource = ISOLAB_SOURCE_DIR;
// Models are built in memory as if they were in models/sdof, so that their records resolve to
// ground_motions/ as the repository's own models' do.
const std::string kModelPath = kSource + "/models/sdof/scaled.yaml";

std::string SdofModel(const std::string& ground_motion) {
  return "units: {force: kN, length: mm, time: s}\n"
         "structure: {type: sdof, mass: 31.7 t, damping: {ratio: 0.0}}\n"
         "isolation:\n"
         "  components:\n"
         "    - {name: k, type: linear_spring, k: 0.2}\n"
         "excitation:\n"
         "  ground_motion: " +
         ground_motion + "\n";
}

// The samples of a PEER AT2 file, read here without isolab's reader: four header lines, then
// numbers.
std::vector<double> At2Samples(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  for (int i = 0; i < 4; ++i) std::getline(in, line);
  std::vector<double> values;
  double value = 0.0;
  while (in >> value) values.push_back(value);
  return values;
}

double Peak(const std::vector<double>& values) {
  double peak = 0.0;
  for (const double v : values) peak = std::max(peak, std::abs(v));
  return peak;
}

// By the tests' brute force (tests/brute_force_spectrum.h), not the library's spectrum that the
// scaling itself uses: it reads a peak at most 2e-5 below the library's and up to 1e-3 above it
// (ElasticSpectrum.AgreesWithTheTestsBruteForceSpectrum).
double SaAt(const integrators::SampledHistory& record, double period, double damping) {
  return isolab::testing::BruteForceSa(record.values, record.dt, period, damping);
}

// `sa` is `target` as the brute force reads the library's.
void ExpectSaReads(double sa, double target) {
  EXPECT_GE(sa, target * (1.0 - 2e-5));
  EXPECT_LE(sa, target * (1.0 + 1e-3));
}

// The model's first ground motion applied alone, its file resolved as Prepare resolves it.
integrators::SampledHistory Applied(const model::ModelFile& model, io::AppliedRecord* applied) {
  model::GroundMotionSection motion = model.excitation.ground_motion.at(0);
  motion.file = kSource + "/models/sdof/" + motion.file;
  integrators::SampledHistory history;
  *applied = ApplyRecord(motion, "units", "dt", model.units, &history);
  return history;
}

TEST(RecordScaling, PgaTargetMatchesTheFilesOwnSamples) {
  const std::string file = kSource + "/ground_motions/elcentro_1940_ns.at2";
  const model::ModelFile model = model::LoadModelText(
      SdofModel("{file: ../../ground_motions/elcentro_1940_ns.at2, scale: {pga: 0.4 g}}"),
      kModelPath);
  io::AppliedRecord applied;
  const integrators::SampledHistory history = Applied(model, &applied);
  const double file_peak = Peak(At2Samples(file));  // in g
  EXPECT_NEAR(applied.scale, 0.4 / file_peak, 1e-12 * applied.scale);
  EXPECT_NEAR(Peak(history.values), 0.4 * kG, 1e-12 * 0.4 * kG);
  EXPECT_NEAR(applied.pga, 0.4 * kG, 1e-12 * 0.4 * kG);
  EXPECT_EQ(applied.scaled_to, "PGA 0.4 g");

  // Through Prepare, as every run, study and Python call gets it.
  const Problem problem = Prepare(model, {});
  ASSERT_EQ(problem.records.size(), 1u);
  EXPECT_EQ(problem.records[0].scale, applied.scale);
  EXPECT_NEAR(problem.records[0].pga, 0.4 * kG, 1e-12 * 0.4 * kG);
  EXPECT_EQ(io::DescribeScale(problem.records[0]),
            fmt::format("scale {:.6g} to PGA 0.4 g", applied.scale));
}

TEST(RecordScaling, PgaTargetInAnyAccelerationUnit) {
  const model::ModelFile model = model::LoadModelText(
      SdofModel("{file: ../../ground_motions/elcentro_1940_ns.at2, scale: {pga: 3.5 m/s^2}}"),
      kModelPath);
  io::AppliedRecord applied;
  const integrators::SampledHistory history = Applied(model, &applied);
  EXPECT_NEAR(Peak(history.values), 3500.0, 1e-12 * 3500.0);
  EXPECT_EQ(applied.scaled_to, "PGA 3.5 m/s^2");
}

// A sine of amplitude A sampled at its crests has PGA A: the factor to a target is target / A.
TEST(RecordScaling, PgaTargetOnASineIsTargetOverAmplitude) {
  io::Record sine;
  sine.path = "sine";
  sine.format = "in memory";
  sine.units = "g";
  sine.units_source = "header";
  sine.dt = 0.05;
  for (int k = 0; k <= 400; ++k) {
    sine.values.push_back(0.25 * std::sin(2.0 * std::numbers::pi * k / 20.0));  // T = 1 s
  }
  ASSERT_EQ(Peak(sine.values), 0.25);
  model::GroundMotionSection motion;
  motion.file = "sine";
  motion.target =
      model::ScaleTarget{model::ScaleTarget::Measure::kPga, 0.4 * kG, 0.0, 0.05, "PGA 0.4 g"};
  integrators::SampledHistory history;
  const io::AppliedRecord applied =
      ApplyRecord(motion, "units", "dt", UnitSystem("kN", "mm", "s"), &history, &sine);
  EXPECT_NEAR(applied.scale, 1.6, 1e-12 * 1.6);
  EXPECT_NEAR(Peak(history.values), 0.4 * kG, 1e-12 * 0.4 * kG);
}

TEST(RecordScaling, SaTargetIsReachedByTheSpectrumOfTheScaledRecord) {
  const model::ModelFile model = model::LoadModelText(
      SdofModel("{file: ../../ground_motions/fwn_firm_seed1.at2, scale: {sa: 0.6 g, period: 2.5 "
                "s, damping: 0.05}}"),
      kModelPath);
  io::AppliedRecord applied;
  const integrators::SampledHistory history = Applied(model, &applied);
  ExpectSaReads(SaAt(history, 2.5, 0.05), 0.6 * kG);
  EXPECT_EQ(applied.scaled_to, "Sa(2.5 s, 5 %) 0.6 g");
  // Sa is linear in the record: the factor is the target over the unscaled record's Sa.
  integrators::SampledHistory unscaled = history;
  for (double& a : unscaled.values) a /= applied.scale;
  EXPECT_NEAR(applied.scale, 0.6 * kG / SaAt(unscaled, 2.5, 0.05), 1e-3 * applied.scale);
}

TEST(RecordScaling, SaTargetDampingDefaultsToFivePercentAndBareNumbersAreModelUnits) {
  const model::ModelFile model = model::LoadModelText(
      SdofModel("{file: ../../ground_motions/fwn_firm_seed1.at2, scale: {sa: 4000, period: 1.5}}"),
      kModelPath);
  ASSERT_TRUE(model.excitation.ground_motion[0].target);
  EXPECT_EQ(model.excitation.ground_motion[0].target->damping, 0.05);
  io::AppliedRecord applied;
  const integrators::SampledHistory history = Applied(model, &applied);
  ExpectSaReads(SaAt(history, 1.5, 0.05), 4000.0);
  EXPECT_EQ(applied.scaled_to, "Sa(1.5 s, 5 %) 4000 mm/s^2");
}

std::string PlanModelWith(const std::string& h1, const std::string& h2, const std::string& v) {
  std::ifstream in(kSource + "/models/plan/five_story_fp_plan.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string model = text.str();
  const auto replace = [&](const std::string& key, const std::string& entry) {
    const std::string start = "    " + key + ": {";
    const std::size_t at = model.find(start);
    EXPECT_NE(at, std::string::npos) << key;
    model.replace(at, model.find('\n', at) - at, "    " + key + ": " + entry);
  };
  replace("h1", h1);
  replace("h2", h2);
  replace("v", v);
  return model;
}

TEST(RecordScaling, APairTakesOneFactorFromH1) {
  const std::string path = kSource + "/models/plan/scaled.yaml";
  const model::ModelFile model = model::LoadModelText(
      PlanModelWith("{file: ../../ground_motions/fwn_firm_seed1.at2, scale: {pga: 0.5 g}}",
                    "{file: ../../ground_motions/h2_fwn_firm_seed3.at2}",
                    "{file: ../../ground_motions/v_fwn_firm_seed4.at2}"),
      path);
  const Problem problem = Prepare(model, {});
  ASSERT_EQ(problem.records.size(), 2u);
  ASSERT_TRUE(problem.vertical_record);
  const double h1_peak = Peak(At2Samples(kSource + "/ground_motions/fwn_firm_seed1.at2"));
  EXPECT_NEAR(problem.records[0].scale, 0.5 / h1_peak, 1e-12 * problem.records[0].scale);
  EXPECT_NEAR(problem.records[0].pga, 0.5 * kG, 1e-12 * 0.5 * kG);
  EXPECT_EQ(problem.records[1].scale, problem.records[0].scale);
  EXPECT_EQ(problem.vertical_record->scale, problem.records[0].scale);
  EXPECT_EQ(problem.records[1].scaled_to, "PGA 0.5 g of h1");
  EXPECT_EQ(problem.vertical_record->scaled_to, "PGA 0.5 g of h1");
}

TEST(RecordScaling, TheCommandLinesScaleReplacesTheTarget) {
  const model::ModelFile model = model::LoadModelText(
      SdofModel("{file: ../../ground_motions/elcentro_1940_ns.at2, scale: {pga: 0.4 g}}"),
      kModelPath);
  RunOverrides overrides;
  overrides.scale = 2.0;
  const Problem problem = Prepare(model, overrides);
  EXPECT_EQ(problem.records[0].scale, 2.0);
  EXPECT_EQ(problem.records[0].scaled_to, "");
  EXPECT_EQ(io::DescribeScale(problem.records[0]), "scale 2");
}

std::string LoadError(const std::string& text) {
  try {
    model::LoadModelText(text, kModelPath);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

void ExpectRefused(const std::string& scale, const std::string& where, const std::string& what) {
  const std::string message = LoadError(
      SdofModel("{file: ../../ground_motions/elcentro_1940_ns.at2, scale: " + scale + "}"));
  EXPECT_NE(message.find(kModelPath + where), std::string::npos) << message;
  EXPECT_NE(message.find(what), std::string::npos) << message;
}

TEST(RecordScaling, BadTargetsAreRefusedWhereTheyAreWritten) {
  // The map starts at column 72 of line 7; its keys follow.
  ExpectRefused("{pgaa: 0.4 g}", ":7:", "excitation.ground_motion.scale");
  ExpectRefused("{pgaa: 0.4 g}", ":7:", "pgaa");
  ExpectRefused("{pga: 0.4 g, sa: 0.6 g, period: 2}",
                ":7:", "excitation.ground_motion.scale: give one target, pga or sa, not both");
  ExpectRefused("{pga: -0.4 g}", ":7:", "excitation.ground_motion.scale.pga");
  ExpectRefused("{pga: 0}", ":7:", "excitation.ground_motion.scale.pga");
  ExpectRefused("{sa: 0.6 g, period: -1 s}", ":7:", "excitation.ground_motion.scale.period");
  ExpectRefused("{sa: 0.6 g}", ":7:", "missing key 'period'");
  ExpectRefused("{pga: 0.4 g, period: 2 s}",
                ":7:", "excitation.ground_motion.scale.period: goes with a target sa");
  ExpectRefused("{sa: 0.6 g, period: 2 s, damping: 1.2}",
                ":7:", "excitation.ground_motion.scale.damping");
  ExpectRefused("{}", ":7:", "{pga: 0.4 g} or {sa: 0.6 g, period: 2.5 s, damping: 0.05}");
  ExpectRefused("{pga: 0.4 kN}", ":7:", "excitation.ground_motion.scale.pga");
  ExpectRefused("[0.4]", ":7:", "excitation.ground_motion.scale");
}

TEST(RecordScaling, AmbiguousPairsAreRefusedNamingTheKey) {
  const auto error = [](const std::string& h1, const std::string& h2) {
    try {
      model::LoadModelText(
          PlanModelWith(h1, h2, "{file: ../../ground_motions/v_fwn_firm_seed4.at2}"),
          kSource + "/models/plan/scaled.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string on_h2 =
      error("{file: ../../ground_motions/fwn_firm_seed1.at2}",
            "{file: ../../ground_motions/h2_fwn_firm_seed3.at2, scale: {pga: 0.4 g}}");
  EXPECT_NE(on_h2.find("scaled.yaml:34:"), std::string::npos) << on_h2;
  EXPECT_NE(on_h2.find("excitation.ground_motion.h2.scale: a target scales the whole record"),
            std::string::npos)
      << on_h2;
  const std::string both =
      error("{file: ../../ground_motions/fwn_firm_seed1.at2, scale: {pga: 0.4 g}}",
            "{file: ../../ground_motions/h2_fwn_firm_seed3.at2, scale: 0.6}");
  EXPECT_NE(both.find("scaled.yaml:34:"), std::string::npos) << both;
  EXPECT_NE(both.find("excitation.ground_motion.h1.scale is a target"), std::string::npos) << both;
}

}  // namespace
}  // namespace isolab::analysis
