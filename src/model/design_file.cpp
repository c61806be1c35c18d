#include "isolab/model/design_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <variant>

#include "isolab/core/errors.h"
#include "isolab/io/target_spectrum_file.h"
#include "isolab/model/build_structure.h"
#include "model_sections.h"

namespace isolab::model {
namespace {

namespace fs = std::filesystem;

// An acceleration in g, given as a number (g) or a quantity with its unit ("0.9 g", "8.8 m/s^2").
double ReadInG(const YamlReader& reader, const YAML::Node& map, const std::string& path,
               const std::string& key, const UnitSystem& units) {
  const YAML::Node node = reader.Require(map, path, key);
  const std::string where = ChildPath(path, key);
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  double bare = 0.0;
  const double value = YAML::convert<double>::decode(node, bare)
                           ? reader.ReadNumber(node, where)
                           : reader.ReadQuantity(node, where, dimension::kAcceleration, units) / g;
  if (!(value > 0.0)) reader.Fail(node, where, fmt::format("{:g} g (must be > 0)", value));
  return value;
}

double ReadSeconds(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                   const UnitSystem& units) {
  return reader.ReadQuantity(node, path, dimension::kTime, units) *
         units.SiFactor(dimension::kTime);
}

spectra::TargetSpectrum ReadTarget(const YamlReader& reader, const YAML::Node& node,
                                   const fs::path& directory, const UnitSystem& units) {
  reader.RequireMap(node, "target");
  reader.CheckKeys(node, "target", {"asce7", "eurocode8", "file"});
  if (node.size() != 1) {
    reader.Fail(node, "target", "give one of asce7, eurocode8 or file");
  }
  spectra::TargetSpectrum target;
  if (node["asce7"]) {
    const YAML::Node a = node["asce7"];
    reader.RequireMap(a, "target.asce7");
    reader.CheckKeys(a, "target.asce7", {"sms", "sm1", "tl"});
    spectra::Asce7Spectrum s;
    s.sms = ReadInG(reader, a, "target.asce7", "sms", units);
    s.sm1 = ReadInG(reader, a, "target.asce7", "sm1", units);
    if (a["tl"]) s.long_period = ReadSeconds(reader, a["tl"], "target.asce7.tl", units);
    target = s;
  } else if (node["eurocode8"]) {
    const YAML::Node e = node["eurocode8"];
    const std::string path = "target.eurocode8";
    reader.RequireMap(e, path);
    // The target is 5 % damped: the ELF procedure applies the bearings' own damping (B_M), and
    // the suite's spectra are 5 % ones.
    reader.CheckKeys(e, path, {"agr", "ground", "type", "importance"});
    spectra::Eurocode8Spectrum s;
    s.agr = ReadInG(reader, e, path, "agr", units);
    if (e["ground"]) {
      const std::string ground = reader.ReadString(e["ground"], path + ".ground");
      if (ground.size() != 1 || ground[0] < 'A' || ground[0] > 'E') {
        reader.Fail(e["ground"], path + ".ground", fmt::format("'{}' (A, B, C, D or E)", ground));
      }
      s.ground = static_cast<spectra::GroundType>(ground[0] - 'A');
    }
    if (e["type"]) {
      s.type = reader.ReadInteger(e["type"], path + ".type");
      if (s.type != 1 && s.type != 2) {
        reader.Fail(e["type"], path + ".type", fmt::format("{} (1 or 2)", s.type));
      }
    }
    if (e["importance"])
      s.importance = ReadPositive(reader, e, path, "importance", dimension::kNone, units);
    target = s;
  } else {
    const std::string file = reader.ReadFilePath(node["file"], "target.file", directory);
    target = io::ReadTargetSpectrumCsv(fs::path(file).lexically_normal().string());
  }
  try {
    spectra::Validate(target);
  } catch (const InvalidParameter& error) {
    reader.Fail(node, "target", error.what());
  }
  return target;
}

std::string TooFew(std::size_t count) {
  return fmt::format(
      "{} (the response-history procedure needs at least {}: EN 1998-1 "
      "4.3.3.4.3; ASCE 7-16 17.3.2 asks for 7, from which the design values are "
      "the suite's mean)",
      count, kMinimumDesignRecords);
}

// Bounds on what a synthetic suite may cost, each named when it is passed: a record of 10,000 s at
// 0.01 s, a hundred pairs.
constexpr double kMaxSyntheticSamples = 1e6;
constexpr int kMaxSyntheticCount = 100;
constexpr double kMaxSyntheticDt = 0.02;  // s

SyntheticSuite ReadSynthetic(const YamlReader& reader, const YAML::Node& node,
                             const UnitSystem& units) {
  const std::string path = "suite.synthetic";
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path, {"count", "seed", "duration", "dt", "tolerance"});
  SyntheticSuite suite;
  if (node["count"]) {
    suite.count = reader.ReadInteger(node["count"], path + ".count");
    if (suite.count < kMinimumDesignRecords) {
      reader.Fail(node["count"], path + ".count", TooFew(suite.count));
    }
    if (suite.count > kMaxSyntheticCount) {
      reader.Fail(node["count"], path + ".count",
                  fmt::format("{} (at most {} pairs: the codes ask for 7 to 11)", suite.count,
                              kMaxSyntheticCount));
    }
  }
  if (node["seed"]) {
    const int seed = reader.ReadInteger(node["seed"], path + ".seed");
    if (seed < 0) reader.Fail(node["seed"], path + ".seed", "must be >= 0");
    suite.seed = static_cast<std::uint64_t>(seed);
  }
  if (node["duration"]) {
    suite.duration = ReadSeconds(reader, node["duration"], path + ".duration", units);
    if (!(suite.duration > 0.0)) reader.Fail(node["duration"], path + ".duration", "must be > 0");
  }
  if (node["dt"]) {
    suite.dt = ReadSeconds(reader, node["dt"], path + ".dt", units);
    if (!(suite.dt > 0.0 && suite.dt < suite.duration / 10)) {
      reader.Fail(node["dt"], path + ".dt", "must be > 0 and a small part of the duration");
    }
    if (suite.dt > kMaxSyntheticDt) {
      reader.Fail(node["dt"], path + ".dt",
                  fmt::format("{:g} s (at most {:g} s: the pairs are matched to the target from "
                              "0.1 s, five samples a period)",
                              suite.dt, kMaxSyntheticDt));
    }
  }
  const double samples = suite.duration / suite.dt;
  if (!(samples <= kMaxSyntheticSamples)) {
    reader.Fail(node["duration"] ? node["duration"] : node, path + ".duration",
                fmt::format("{:g} s at dt = {:g} s is {:.3g} samples a record; at most {:g} (a "
                            "record of {:g} s at that step)",
                            suite.duration, suite.dt, samples, kMaxSyntheticSamples,
                            kMaxSyntheticSamples * suite.dt));
  }
  if (node["tolerance"])
    suite.tolerance = ReadPositive(reader, node, path, "tolerance", dimension::kNone, units);
  return suite;
}

// The model a design runs, refused where a design cannot run it.
void ReadDesignModel(const YamlReader& reader, const YAML::Node& root, const fs::path& directory,
                     DesignFile& design) {
  const YAML::Node model_node = reader.Require(root, "", "model");
  design.model_path =
      fs::path(reader.ReadFilePath(model_node, "model", directory)).lexically_normal().string();
  design.model = LoadModelFile(design.model_path);
  if (!design.model.structure) {
    reader.Fail(model_node, "model",
                fmt::format("'{}' has no structure (a design runs a building: structure or plan)",
                            design.model_path));
  }
  if (design.model.modifications.empty()) {
    reader.Fail(model_node, "model",
                fmt::format("'{}' gives no property modification factors (a bearing type's "
                            "`modification`: docs/design.md); a design runs the upper and lower "
                            "bounds they give",
                            design.model_path));
  }
  if (design.model.axial_load && design.model.axial_load->vertical) {
    reader.Fail(model_node, "model",
                fmt::format("'{}' asks for the vertical component's axial loads "
                            "(axial_load.vertical: true), and a design's suite has none: its "
                            "records are horizontal (pairs in plan), given or synthetic. Design "
                            "with vertical: false (the static shares and overturning stay)",
                            design.model_path));
  }
  if (const auto* isolators = PlanIsolators(design.model)) {
    const bool one_point = std::all_of(isolators->begin(), isolators->end(), [&](const auto& i) {
      return i.position.x == isolators->front().position.x &&
             i.position.y == isolators->front().position.y;
    });
    if (one_point) {
      reader.Fail(model_node, "model",
                  fmt::format("'{}' stands on {} at one point of its plan: nothing in the "
                              "isolation resists its torsion, which a design's accidental "
                              "eccentricity drives (give the isolators their own positions)",
                              design.model_path,
                              isolators->size() == 1 ? "one isolator" : "isolators all"));
    }
  }
}

// The target spectrum, the code it sets, and that code's factors (r_i, gamma_x).
void ReadTargetAndFactors(const YamlReader& reader, const YAML::Node& root,
                          const fs::path& directory, DesignFile& design) {
  const UnitSystem& units = design.model.units;
  const YAML::Node target = reader.Require(root, "", "target");
  design.target = ReadTarget(reader, target, directory, units);
  design.target_key = fmt::format("{}: target", reader.Locate(target).Describe());
  if (std::holds_alternative<spectra::Eurocode8Spectrum>(design.target)) {
    design.code = DesignCode::kEn1998_1;
    design.gamma_x = kRecommendedReliabilityFactor;
    design.period_range[0] = 0.2;
    design.period_range[1] = 2.0;
  }
  if (root["r_i"]) {
    if (design.code != DesignCode::kAsce7_16) {
      reader.Fail(root["r_i"], "r_i",
                  "is ASCE 7-16's response modification of the structure above the isolation "
                  "(17.5.4.2), and the target is eurocode8: EN 1998-1's rules for the "
                  "superstructure are not applied here (remove r_i)");
    }
    design.r_i = reader.ReadNumber(root["r_i"], "r_i");
    if (!(design.r_i >= 1.0 && design.r_i <= 2.0)) {
      reader.Fail(root["r_i"], "r_i",
                  fmt::format("{:g} (R_I = 3/8 R, not below 1 nor above 2: ASCE 7-16 17.5.4.2)",
                              design.r_i));
    }
  }
  if (root["gamma_x"]) {
    if (design.code != DesignCode::kEn1998_1) {
      reader.Fail(root["gamma_x"], "gamma_x",
                  "is Eurocode 8's reliability factor on the isolators' displacements (EN 1998-1 "
                  "10.3(2)), and the target is not eurocode8: an ASCE 7-16 design has its ELF "
                  "floors instead (remove gamma_x)");
    }
    design.gamma_x = reader.ReadNumber(root["gamma_x"], "gamma_x");
    if (!(design.gamma_x >= 1.0 && design.gamma_x <= 2.0)) {
      reader.Fail(root["gamma_x"], "gamma_x",
                  fmt::format("{:g} (a factor on displacements in [1, 2]; EN 1998-1 recommends "
                              "{:g})",
                              design.gamma_x, kRecommendedReliabilityFactor));
    }
  }
}

// The suite's records: given (files or pairs), or synthetic.
void ReadSuiteRecords(const YamlReader& reader, const YAML::Node& suite, const fs::path& directory,
                      DesignFile& design) {
  const UnitSystem& units = design.model.units;
  if (suite["records"] && suite["synthetic"]) {
    reader.Fail(suite, "suite", "give records or synthetic, not both");
  }
  const int directions = Directions(design.model);
  if (suite["records"]) {
    design.records = ReadRecords(reader, suite["records"], "suite.records", directory, units,
                                 directions, design.model_path);
    for (std::size_t i = 0; i < design.records.size(); ++i) {
      for (const GroundMotionSection& c : design.records[i].components) {
        if (c.target) {
          reader.Fail(suite["records"], IndexPath("suite.records", i),
                      fmt::format("{}: the design scales its suite to the target spectrum; give "
                                  "the record without a target (a number, or no scale)",
                                  c.key));
        }
      }
    }
    if (design.records.size() < kMinimumDesignRecords) {
      reader.Fail(suite["records"], "suite.records",
                  fmt::format("{} records{}", TooFew(design.records.size()),
                              directions == 2 ? " (pairs, for a building in plan)" : ""));
    }
    if (directions == 2) {
      for (std::size_t i = 0; i < design.records.size(); ++i) {
        if (design.records[i].components.size() != 2) {
          reader.Fail(suite["records"], IndexPath("suite.records", i),
                      "a building in plan is designed for record pairs {h1, h2}, each pair's "
                      "maximum-direction spectrum scaled to the target");
        }
      }
    }
  } else if (suite["synthetic"]) {
    design.synthetic = ReadSynthetic(reader, suite["synthetic"], units);
    const double model_dt = design.model.analysis.dt * units.SiFactor(dimension::kTime);
    if (design.synthetic->dt < model_dt * (1 - 1e-12)) {
      const YAML::Node dt = suite["synthetic"]["dt"];
      reader.Fail(dt ? dt : suite["synthetic"], "suite.synthetic.dt",
                  fmt::format("{:g} s is finer than the model's analysis.dt, {:g} s: a run "
                              "cannot take a record on a coarser step than its own (give dt >= "
                              "{:g} s, or a finer analysis.dt in '{}')",
                              design.synthetic->dt, model_dt, model_dt, design.model_path));
    }
  } else {
    reader.Fail(suite, "suite", "give records (files or pairs) or synthetic");
  }
}

void ReadPeriodRange(const YamlReader& reader, const YAML::Node& suite, DesignFile& design) {
  if (suite["period_range"]) {
    const YAML::Node range = suite["period_range"];
    if (!range.IsSequence() || range.size() != 2) {
      reader.Fail(range, "suite.period_range",
                  "expected [lower, upper] factors, e.g. [0.75, 1.25]");
    }
    for (int i = 0; i < 2; ++i) {
      design.period_range[i] = reader.ReadNumber(range[i], IndexPath("suite.period_range", i));
    }
    if (!(design.period_range[0] > 0.0 && design.period_range[0] <= 1.0 &&
          design.period_range[1] >= 1.0)) {
      reader.Fail(range, "suite.period_range",
                  fmt::format("[{:g}, {:g}] (0 < lower <= 1 <= upper: the range must hold T_M)",
                              design.period_range[0], design.period_range[1]));
    }
  }
}

// The orientations each pair runs in; a record's name that another would take turned is refused.
void ReadOrientations(const YamlReader& reader, const YAML::Node& suite, DesignFile& design) {
  const int directions = Directions(design.model);
  if (directions == 2) design.orientations = {0.0, 90.0};
  if (suite["orientations"]) {
    const YAML::Node node = suite["orientations"];
    const std::string key = "suite.orientations";
    if (!node.IsSequence() || node.size() == 0 || node.size() > kMaxOrientations) {
      reader.Fail(node, key,
                  fmt::format("expected a list of 1 to {} angles (degrees from x to H1), e.g. "
                              "[0, 90]",
                              kMaxOrientations));
    }
    design.orientations.clear();
    for (std::size_t i = 0; i < node.size(); ++i) {
      const double angle = reader.ReadNumber(node[i], IndexPath(key, i));
      if (!(angle >= 0.0 && angle < 360.0)) {
        reader.Fail(node[i], IndexPath(key, i), fmt::format("{:g} (degrees in [0, 360))", angle));
      }
      if (std::find(design.orientations.begin(), design.orientations.end(), angle) !=
          design.orientations.end()) {
        reader.Fail(node[i], IndexPath(key, i), fmt::format("{:g} is given twice", angle));
      }
      design.orientations.push_back(angle);
    }
    if (directions == 1 && design.orientations != std::vector<double>{0.0}) {
      reader.Fail(node, key,
                  fmt::format("'{}' moves in one direction: its records run along x alone, with "
                              "no orientation to turn (give [0], or a model in plan)",
                              design.model_path));
    }
  }
  // A pair turned by an angle runs under its name + "_at<angle>": no given record may be named so.
  for (const StudyRecord& record : design.records) {
    for (const double angle : design.orientations) {
      const std::string turned = fmt::format("{}_at{:g}", record.name, angle);
      const auto clash = std::find_if(design.records.begin(), design.records.end(),
                                      [&](const StudyRecord& r) { return r.name == turned; });
      if (angle != 0.0 && clash != design.records.end()) {
        reader.Fail(suite["records"], "suite.records",
                    fmt::format("'{}' is also the name '{}' runs under turned by {:g} degrees "
                                "(give the record another name)",
                                turned, record.name, angle));
      }
    }
  }
}

// Whether any isolator's laws include an HDR bearing, in one direction or in plan.
bool HasHdrBearing(const ModelFile& model) {
  const auto hdr = [](const hysteresis::LawParameters& law) {
    return law.type() == hysteresis::LawType::kHdrBearing;
  };
  for (const hysteresis::Component& c : model.isolation.components()) {
    if (hdr(c.parameters)) return true;
  }
  if (const auto* isolators = PlanIsolators(model)) {
    for (const structure::PlanIsolatorSite& site : *isolators) {
      for (const hysteresis::PlanComponent& c : site.assembly.components()) {
        if (hdr(c.law)) return true;
      }
    }
  }
  return false;
}

// The accidental eccentricity and the limits the checks compare with.
void ReadEccentricityAndLimits(const YamlReader& reader, const YAML::Node& root,
                               DesignFile& design) {
  const int directions = Directions(design.model);
  if (directions == 1) design.eccentricity = 0.0;
  if (root["eccentricity"]) {
    design.eccentricity = reader.ReadNumber(root["eccentricity"], "eccentricity");
    if (design.eccentricity != 0.0 && directions == 1) {
      reader.Fail(root["eccentricity"], "eccentricity",
                  fmt::format("{:g}: accidental eccentricity shifts floors in plan, and '{}' "
                              "moves in one direction (give 0, or a model in plan)",
                              design.eccentricity, design.model_path));
    }
    if (!(design.eccentricity >= 0.0 && design.eccentricity < 0.5)) {
      reader.Fail(root["eccentricity"], "eccentricity",
                  fmt::format("{:g} (a fraction of the plan dimension, 0 <= e < 0.5)",
                              design.eccentricity));
    }
  }
  if (root["drift_limit"]) {
    design.drift_limit = reader.ReadNumber(root["drift_limit"], "drift_limit");
    if (!(design.drift_limit > 0.0 && design.drift_limit < 1.0)) {
      reader.Fail(
          root["drift_limit"], "drift_limit",
          fmt::format("{:g} (a story drift ratio in (0, 1): 0.015 for 1.5 %)", design.drift_limit));
    }
  }
  if (root["shear_strain_limit"]) {
    design.shear_strain_limit = reader.ReadNumber(root["shear_strain_limit"], "shear_strain_limit");
    if (!(design.shear_strain_limit > 0.0 && design.shear_strain_limit <= 10.0)) {
      reader.Fail(root["shear_strain_limit"], "shear_strain_limit",
                  fmt::format("{:g} (a ratio of rubber shear strain, 0 < limit <= 10: 2.5 for "
                              "250 %)",
                              design.shear_strain_limit));
    }
    // It sets an HDR bearing's displacement capacity, and no other law's.
    if (!HasHdrBearing(design.model)) {
      reader.Fail(root["shear_strain_limit"], "shear_strain_limit",
                  fmt::format("sets the displacement capacity of HDR bearings (hdr_bearing), and "
                              "'{}' has none: leave it out",
                              design.model_path));
    }
  }
}

}  // namespace

std::string_view CodeName(DesignCode code) {
  return code == DesignCode::kEn1998_1 ? "EN 1998-1:2004" : "ASCE 7-16";
}

DesignFile LoadDesignFile(const std::string& path) {
  const YamlReader reader(path);
  const YAML::Node root = reader.LoadFile();
  reader.RequireMap(root, "");
  reader.CheckKeys(root, "",
                   {"description", "model", "target", "suite", "eccentricity", "drift_limit",
                    "shear_strain_limit", "gamma_x", "r_i", "output"});
  DesignFile design;
  design.path = path;
  const fs::path directory = fs::path(path).parent_path();
  if (root["description"]) {
    design.description = reader.ReadString(root["description"], "description");
  }
  ReadDesignModel(reader, root, directory, design);
  ReadTargetAndFactors(reader, root, directory, design);
  const YAML::Node suite = reader.Require(root, "", "suite");
  reader.RequireMap(suite, "suite");
  reader.CheckKeys(suite, "suite", {"records", "synthetic", "period_range", "orientations"});
  design.suite_key = fmt::format("{}: suite", reader.Locate(suite).Describe());
  ReadSuiteRecords(reader, suite, directory, design);
  ReadPeriodRange(reader, suite, design);
  ReadOrientations(reader, suite, design);
  ReadEccentricityAndLimits(reader, root, design);
  if (root["output"]) {
    const YAML::Node output = root["output"];
    reader.RequireMap(output, "output");
    reader.CheckKeys(output, "output", {"directory"});
    if (output["directory"]) {
      design.output_directory = reader.ReadName(output["directory"], "output.directory");
    }
  }
  return design;
}

}  // namespace isolab::model
