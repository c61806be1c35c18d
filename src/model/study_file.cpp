#include "isolab/model/study_file.h"

#include <fmt/format.h>
#include <glob.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <span>
#include <string_view>
#include <utility>

#include "isolab/io/record.h"
#include "isolab/model/build_structure.h"
#include "model_sections.h"

namespace isolab::model {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kStudyKeys[] = {"description", "building", "variants", "reference",
                                           "records",     "scales",   "output",   "free_vibration"};
constexpr std::string_view kVariantKeys[] = {"name", "isolation", "model", "fixed_base"};

bool ReadFlag(const YamlReader& reader, const YAML::Node& node, const std::string& path) {
  const std::string text = reader.ReadString(node, path);
  if (text == "true") return true;
  if (text == "false") return false;
  reader.Fail(node, path, fmt::format("'{}' is not true or false", text));
}

// Variant names become folder names of the per-run results, so they stay portable.
void CheckName(const YamlReader& reader, const YAML::Node& node, const std::string& path,
               const std::string& name) {
  const bool portable =
      !name.empty() && name != "." && name != ".." &&
      std::all_of(name.begin(), name.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
      });
  if (!portable) {
    reader.Fail(node, path,
                fmt::format("'{}' (a name takes letters, digits, '_', '-' and '.')", name));
  }
}

// A model file named at `node`, relative to the study's folder.
std::string ModelPath(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                      const fs::path& directory) {
  return fs::path(reader.ReadFilePath(node, path, directory)).lexically_normal().string();
}

// What a model moves in, for messages.
std::string DescribeDirections(int directions) {
  return directions == 2 ? "in plan (x, y and rotation)" : "in one direction";
}

ModelFile LoadStructureModel(const YamlReader& reader, const YAML::Node& node,
                             const std::string& path, const std::string& file) {
  ModelFile model = LoadModelFile(file);
  if (!model.structure) {
    reader.Fail(node, path, fmt::format("'{}' has no structure section: nothing to run", file));
  }
  return model;
}

// What a model's stored text gains when a variant replaces its isolation: results files keep
// the model's YAML as the record of what ran.
std::string ReplacedIsolationNote(const std::string& study_path, const std::string& variant,
                                  const YAML::Node& node) {
  YAML::Emitter emitter;
  emitter << YAML::Flow << node;
  return fmt::format(
      "\n# isolab compare, study {}, variant {}: the isolation above is replaced by\n# isolation: "
      "{}\n",
      study_path, variant, emitter.c_str());
}

// A variant entry's keys checked and its name read.
StudyVariant NamedVariant(const YamlReader& reader, const YAML::Node& node,
                          const std::string& path) {
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path, kVariantKeys);
  StudyVariant variant;
  const std::string name_path = ChildPath(path, "name");
  variant.name = reader.ReadString(reader.Require(node, path, "name"), name_path);
  CheckName(reader, node["name"], name_path, variant.name);
  return variant;
}

StudyVariant ReadVariant(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                         const fs::path& directory, const ModelFile& building) {
  StudyVariant variant = NamedVariant(reader, node, path);
  if (node["fixed_base"]) {
    variant.fixed_base = ReadFlag(reader, node["fixed_base"], ChildPath(path, "fixed_base"));
  }
  if (node["isolation"] && node["model"]) {
    reader.Fail(node, path, "give isolation or model, not both");
  }
  if (node["model"]) {
    const std::string model_path = ChildPath(path, "model");
    const std::string file = ModelPath(reader, node["model"], model_path, directory);
    variant.model = LoadStructureModel(reader, node["model"], model_path, file);
    if (Directions(variant.model) != Directions(building)) {
      reader.Fail(node["model"], model_path,
                  fmt::format("'{}' moves {} and the building '{}' {}: a study's variants move "
                              "in the same directions, under the same records",
                              file, DescribeDirections(Directions(variant.model)), building.path,
                              DescribeDirections(Directions(building))));
    }
  } else if (node["isolation"]) {
    const std::string isolation_path = ChildPath(path, "isolation");
    if (variant.fixed_base) {
      reader.Fail(node["fixed_base"], ChildPath(path, "fixed_base"),
                  "a fixed-base variant has no isolation; remove one of the two");
    }
    const StructureSection& structure = *building.structure;
    if (structure.kind == StructureSection::Kind::kShearBuilding &&
        !(structure.building.base_mass > 0.0)) {
      reader.Fail(node["isolation"], isolation_path,
                  fmt::format("the building '{}' has no base_mass, which an isolated building "
                              "needs",
                              building.path));
    }
    // A plan isolator's coupling, as the model's own isolators take it; the rest is the
    // isolation section every model reads.
    YAML::Node isolation = node["isolation"];
    bool uncoupled = false;
    if (isolation.IsMap() && isolation["coupling"]) {
      const std::string key = ChildPath(isolation_path, "coupling");
      if (structure.kind != StructureSection::Kind::kPlanBuilding) {
        reader.Fail(isolation["coupling"], key,
                    fmt::format("applies to the isolators of a building in plan; '{}' moves in "
                                "one direction",
                                building.path));
      }
      const std::string coupling = reader.ReadString(isolation["coupling"], key);
      if (coupling != "coupled" && coupling != "uncoupled") {
        reader.Fail(isolation["coupling"], key,
                    fmt::format("'{}' (expected coupled or uncoupled)", coupling));
      }
      uncoupled = coupling == "uncoupled";
      isolation = YAML::Clone(isolation);  // the file's own node stays as written
      isolation.remove("coupling");
    }
    std::optional<identification::IdentifiedRange> range;
    const hysteresis::ParallelAssembly laws = ReadIsolation(
        reader, isolation, isolation_path, directory, building.units, nullptr, nullptr, &range);
    const std::size_t c = FirstWithoutCoupledForm(laws);
    if (structure.kind == StructureSection::Kind::kPlanBuilding && !uncoupled && c < laws.size()) {
      reader.Fail(node["isolation"], isolation_path,
                  fmt::format("{}: every isolator of a building in plan takes these laws as "
                              "coupled laws (give the variant's isolation coupling: uncoupled to "
                              "use them along x and y independently)",
                              NoCoupledForm(laws, c)));
    }
    variant.model = building;
    ReplaceIsolation(&variant.model, laws, std::move(range), uncoupled);
    variant.model.text += ReplacedIsolationNote(reader.file(), variant.name, node["isolation"]);
  } else {
    variant.model = building;
  }
  if (variant.fixed_base) {
    if (variant.model.structure->kind == StructureSection::Kind::kSdof) {
      reader.Fail(node["fixed_base"], ChildPath(path, "fixed_base"),
                  "applies to a building on isolators; an SDOF has no base to hold");
    }
    variant.model.text +=
        fmt::format("\n# isolab compare, study {}, variant {}: run on a fixed base\n",
                    reader.file(), variant.name);
  }
  return variant;
}

bool IsGlob(std::string_view pattern) {
  return pattern.find_first_of("*?[") != std::string_view::npos;
}

// The paths matching `pattern`, in byte order (glob(3) would sort by the
// locale's collation, which differs between machines).
std::vector<std::string> ExpandGlob(const std::string& pattern) {
  glob_t matches{};
  const int status = glob(pattern.c_str(), GLOB_NOSORT, nullptr, &matches);
  std::vector<std::string> files;
  if (status == 0) {
    for (std::size_t i = 0; i < matches.gl_pathc; ++i) files.emplace_back(matches.gl_pathv[i]);
  }
  globfree(&matches);
  std::sort(files.begin(), files.end());
  return files;
}

// A record entry's {file, units, dt, scale}, or a plain file name or glob: one component, whose
// file is the entry's pattern.
StudyRecord ReadRecordEntry(const YamlReader& reader, const YAML::Node& node,
                            const std::string& path, const UnitSystem& units) {
  StudyRecord given;
  given.entry = fmt::format("{}: {}", reader.Locate(node).Describe(), path);
  GroundMotionSection component;
  if (node.IsMap()) {
    component = ReadGroundMotion(reader, node, path, units);
  } else {
    component.file = reader.ReadString(node, path);
  }
  component.location = reader.Locate(node);
  given.components.push_back(component);
  return given;
}

// `file`: a component's file resolved against the study's folder; it must exist.
void ResolveComponent(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                      const fs::path& directory, GroundMotionSection* component) {
  component->file = (directory / component->file).lexically_normal().string();
  std::error_code error;
  if (!fs::is_regular_file(component->file, error)) {
    reader.Fail(node["file"], ChildPath(path, "file"),
                fmt::format("'{}' is not a file", component->file));
  }
  if (!(component->scale > 0.0) || !std::isfinite(component->scale)) {
    reader.Fail(node["scale"], ChildPath(path, "scale"),
                fmt::format("{:g} (must be a finite number > 0)", component->scale));
  }
}

// Both components read as their runs will read them: a pair must share its step and its length
// (problem.h), and a study refuses one that does not before any run starts.
void CheckPairMatches(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                      const StudyRecord& pair, const UnitSystem& units) {
  const auto read = [&](const GroundMotionSection& component, const std::string& key) {
    const std::string where = fmt::format("{}.{} in {}", path, key, reader.file());
    return io::ReadRecord(component.file,
                          {component.units, component.dt * units.SiFactor(dimension::kTime),
                           where + ".units", where + ".dt"});
  };
  const io::Record h1 = read(pair.components[0], "h1"), h2 = read(pair.components[1], "h2");
  const std::string h2_path = ChildPath(path, "h2");
  if (std::abs(h2.dt - h1.dt) > 1e-9 * h1.dt) {
    reader.Fail(node["h2"], h2_path,
                fmt::format("'{}' has a step of {:g} s, h1 '{}' {:g} s; a pair must share one step",
                            h2.path, h2.dt, h1.path, h1.dt));
  }
  if (h2.values.size() != h1.values.size()) {
    reader.Fail(node["h2"], h2_path,
                fmt::format("'{}' has {} samples, h1 '{}' {}; a pair must have the same length",
                            h2.path, h2.values.size(), h1.path, h1.values.size()));
  }
}

bool IsPairEntry(const YAML::Node& node) { return node.IsMap() && (node["h1"] || node["h2"]); }

// A record entry {h1, h2, angle, name}, as a model's excitation.ground_motion pair.
StudyRecord ReadPairEntry(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                          const fs::path& directory, const UnitSystem& units) {
  reader.CheckKeys(node, path, {"h1", "h2", "angle", "name"});
  StudyRecord record;
  record.entry = fmt::format("{}: {}", reader.Locate(node).Describe(), path);
  for (const char* key : {"h1", "h2"}) {
    const std::string component_path = ChildPath(path, key);
    const YAML::Node component = reader.Require(node, path, key);
    GroundMotionSection section = ReadGroundMotion(reader, component, component_path, units);
    ResolveComponent(reader, component, component_path, directory, &section);
    record.components.push_back(std::move(section));
  }
  if (record.components[1].target) {
    reader.Fail(node["h2"]["scale"], ChildPath(path, "h2.scale"),
                "a pair takes its target on h1, whose factor scales h2 too");
  }
  if (node["angle"])
    record.angle = ReadRecordAngle(reader, node["angle"], ChildPath(path, "angle"));
  CheckPairMatches(reader, node, path, record, units);
  if (node["name"]) {
    record.name = reader.ReadString(node["name"], ChildPath(path, "name"));
    CheckName(reader, node["name"], ChildPath(path, "name"), record.name);
  } else {
    record.name = fs::path(record.components[0].file).stem().string();
  }
  return record;
}

// Records become runs' file names: two with one name would overwrite each other's results.
void AddRecord(const YamlReader& reader, const YAML::Node& node, const std::string& path,
               StudyRecord record, std::vector<StudyRecord>* records) {
  const auto same = std::find_if(records->begin(), records->end(),
                                 [&](const StudyRecord& r) { return r.name == record.name; });
  if (same != records->end()) {
    reader.Fail(node, path,
                fmt::format("'{}' has the name '{}' of '{}' (record names are file stems, or a "
                            "pair's name, and must be unique)",
                            record.components[0].file, record.name, same->components[0].file));
  }
  records->push_back(std::move(record));
}

std::vector<double> ReadScales(const YamlReader& reader, const YAML::Node& list) {
  reader.RequireSequence(list, "scales");
  if (list.size() == 0) reader.Fail(list, "scales", "the list is empty");
  std::vector<double> scales;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = IndexPath("scales", i);
    const double scale = reader.ReadNumber(list[i], path);
    if (!(scale > 0.0) || !std::isfinite(scale)) {
      reader.Fail(list[i], path, fmt::format("{:g} (must be a finite number > 0)", scale));
    }
    if (std::find(scales.begin(), scales.end(), scale) != scales.end()) {
      reader.Fail(list[i], path, fmt::format("{:g} is already in the list", scale));
    }
    scales.push_back(scale);
  }
  return scales;
}

}  // namespace

std::vector<StudyRecord> ReadRecords(const YamlReader& reader, const YAML::Node& list,
                                     const std::string& key, const fs::path& directory,
                                     const UnitSystem& units, int directions,
                                     const std::string& building) {
  reader.RequireSequence(list, key);
  if (list.size() == 0) reader.Fail(list, key, "the list is empty (give files or globs)");
  std::vector<StudyRecord> records;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string path = IndexPath(key, i);
    if (IsPairEntry(list[i])) {
      if (directions < 2) {
        reader.Fail(list[i], path,
                    fmt::format("a pair of records drives a building in plan; the building '{}' "
                                "moves in one direction (give one record per entry)",
                                building));
      }
      AddRecord(reader, list[i], path, ReadPairEntry(reader, list[i], path, directory, units),
                &records);
      continue;
    }
    const StudyRecord given = ReadRecordEntry(reader, list[i], path, units);
    const std::string& entry = given.components[0].file;
    const std::string pattern = (directory / entry).lexically_normal().string();
    std::vector<std::string> files;
    std::error_code error;
    // A file that is there is that file, whatever characters its name has ("rec[1].at2").
    if (IsGlob(entry) && !fs::exists(pattern, error)) {
      files = ExpandGlob(pattern);
      // A folder the pattern matches is not a record; anything else that is not a file (a broken
      // link, a pipe) would be a record silently missing from the suite.
      std::erase_if(files, [&](const std::string& file) { return fs::is_directory(file, error); });
      for (const std::string& file : files) {
        if (!fs::is_regular_file(file, error)) {
          reader.Fail(list[i], path,
                      fmt::format("'{}' (matched by '{}') is not a file", file, pattern));
        }
      }
      if (files.empty()) reader.Fail(list[i], path, fmt::format("'{}' matches no file", pattern));
    } else {
      if (!fs::is_regular_file(pattern, error)) {
        reader.Fail(list[i], path, fmt::format("'{}' is not a file", pattern));
      }
      files.push_back(pattern);
    }
    for (const std::string& file : files) {
      StudyRecord record = given;
      record.name = fs::path(file).stem().string();
      record.components[0].file = file;
      AddRecord(reader, list[i], path, std::move(record), &records);
    }
  }
  return records;
}

StudyFile LoadStudyFile(const std::string& path) {
  const YamlReader reader(path);
  const YAML::Node root = reader.LoadFile();
  reader.RequireMap(root, "");
  reader.CheckKeys(root, "", kStudyKeys);
  StudyFile study;
  study.path = path;
  const fs::path directory = fs::path(path).parent_path();
  if (root["description"]) {
    study.description = reader.ReadString(root["description"], "description");
  }
  const YAML::Node building_node = reader.Require(root, "", "building");
  const std::string building_file = ModelPath(reader, building_node, "building", directory);
  const ModelFile building = LoadStructureModel(reader, building_node, "building", building_file);
  study.units = building.units;
  study.directions = Directions(building);
  study.rotations = study.directions == 2;
  study.building_path = building_file;

  const YAML::Node variants = reader.Require(root, "", "variants");
  reader.RequireSequence(variants, "variants");
  if (variants.size() == 0) reader.Fail(variants, "variants", "the list is empty");
  std::vector<std::string> names;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const std::string variant_path = IndexPath("variants", i);
    study.variants.push_back(ReadVariant(reader, variants[i], variant_path, directory, building));
    const std::string& name = study.variants.back().name;
    const auto same = std::find(names.begin(), names.end(), name);
    if (same != names.end()) {
      reader.Fail(
          variants[i]["name"], ChildPath(variant_path, "name"),
          fmt::format("'{}' is already the name of variants[{}]", name, same - names.begin()));
    }
    names.push_back(name);
  }
  if (root["reference"]) {
    const std::string reference = reader.ReadString(root["reference"], "reference");
    const auto found = std::find(names.begin(), names.end(), reference);
    if (found == names.end()) {
      const std::vector<std::string_view> candidates(names.begin(), names.end());
      const std::string_view nearest = NearestWord(reference, candidates);
      reader.Fail(
          root["reference"], "reference",
          fmt::format("'{}' is not a variant{}", reference,
                      nearest.empty() ? "" : fmt::format(" (did you mean '{}'?)", nearest)));
    }
    study.reference = static_cast<std::size_t>(found - names.begin());
  }
  study.records = ReadRecords(reader, reader.Require(root, "", "records"), "records", directory,
                              study.units, study.directions, study.building_path);
  study.scales = ReadScales(reader, reader.Require(root, "", "scales"));
  if (const YAML::Node free = root["free_vibration"]) {
    SetStudyFreeVibration(study, ReadFreeVibration(reader, free, "free_vibration", study.units),
                          reader.Locate(free).Describe() + ": free_vibration");
  }
  if (root["output"]) {
    const YAML::Node output = root["output"];
    reader.RequireMap(output, "output");
    reader.CheckKeys(output, "output", {"directory", "runs"});
    if (output["directory"]) {
      study.output_directory = reader.ReadName(output["directory"], "output.directory");
    }
    if (output["runs"]) {
      const std::string runs = reader.ReadString(output["runs"], "output.runs");
      try {
        study.runs = ParseRunFiles(runs, "output.runs");
      } catch (const InputError&) {
        throw InputError(reader.Locate(output["runs"]),
                         fmt::format("output.runs = {} (must be none, summary or full)", runs));
      }
    }
  }
  return study;
}

RunFiles ParseRunFiles(const std::string& text, const std::string& key) {
  for (const RunFiles runs : {RunFiles::kNone, RunFiles::kSummary, RunFiles::kFull}) {
    if (text == RunFilesName(runs)) return runs;
  }
  throw InputError({key}, fmt::format("{} (must be none, summary or full)", text));
}

const char* RunFilesName(RunFiles runs) {
  switch (runs) {
    case RunFiles::kNone:
      return "none";
    case RunFiles::kSummary:
      return "summary";
    case RunFiles::kFull:
      return "full";
  }
  return "?";
}

void SetStudyFreeVibration(StudyFile& study, const FreeVibration& free,
                           const std::string& given_by) {
  for (const StudyVariant& variant : study.variants) {
    if (variant.model.analysis.duration > 0.0) {
      throw InputError({given_by},
                       fmt::format("variant '{}' fixes the run's duration (analysis.duration in "
                                   "{}); free vibration cannot lengthen it",
                                   variant.name, variant.model.path));
    }
  }
  study.free_vibration = free;
  study.free_vibration_given_by = given_by;
}

}  // namespace isolab::model
