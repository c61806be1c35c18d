#include "isolab/model/building_fit_spec_file.h"

#include <fmt/format.h>

#include <filesystem>

#include "model_sections.h"

namespace isolab::model {

BuildingFitSpecFile LoadBuildingFitSpec(const std::string& path) {
  const YamlReader reader(path);
  const YAML::Node root = reader.LoadFile();
  reader.RequireMap(root, "");
  reader.CheckKeys(root, "",
                   {"description", "model", "input", "parameters", "channels", "band", "pause",
                    "substeps", "priors"});
  BuildingFitSpecFile spec;
  spec.path = path;
  spec.model = reader.ReadFilePath(reader.Require(root, "", "model"), "model",
                                   std::filesystem::path(path).parent_path());
  if (const YAML::Node input = root["input"]) {
    const std::string word = reader.ReadString(input, "input");
    if (word != "table" && word != "force") {
      reader.Fail(input, "input",
                  fmt::format("'{}': expected table (shake-table motions) or force (force-driven "
                              "tests: time, displacement and force)",
                              word));
    }
    spec.force_driven = word == "force";
  }
  const YAML::Node parameters = reader.Require(root, "", "parameters");
  reader.RequireSequence(parameters, "parameters");
  if (parameters.size() == 0) reader.Fail(parameters, "parameters", "expected at least one");
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const std::string at = IndexPath("parameters", i);
    const YAML::Node entry = parameters[i];
    BuildingFitParameterEntry parameter;
    parameter.where = reader.Locate(entry);
    if (entry.IsScalar()) {
      parameter.name = reader.ReadString(entry, at);
    } else {
      reader.RequireMap(entry, at);
      reader.CheckKeys(entry, at, {"name", "range", "start"});
      parameter.name = reader.ReadString(reader.Require(entry, at, "name"), at + ".name");
      if (const YAML::Node range = entry["range"]) {
        reader.RequireSequence(range, at + ".range");
        if (range.size() != 2) reader.Fail(range, at + ".range", "expected [low, high]");
        parameter.low = reader.ReadNumber(range[0], at + ".range");
        parameter.high = reader.ReadNumber(range[1], at + ".range");
        if (!(*parameter.high > *parameter.low)) {
          reader.Fail(range, at + ".range", "expected low < high");
        }
      }
      if (entry["start"]) parameter.start = reader.ReadNumber(entry["start"], at + ".start");
      if (parameter.start && parameter.low &&
          !(*parameter.start >= *parameter.low && *parameter.start <= *parameter.high)) {
        reader.Fail(entry["start"], at + ".start", "must lie in the range");
      }
    }
    for (std::size_t j = 0; j < spec.parameters.size(); ++j) {
      if (spec.parameters[j].name == parameter.name) {
        reader.Fail(entry, at,
                    fmt::format("'{}' is fitted twice (also {}): one parameter, one entry",
                                parameter.name, IndexPath("parameters", j)));
      }
    }
    spec.parameters.push_back(std::move(parameter));
  }
  if (const YAML::Node priors = root["priors"]) {
    std::vector<std::string> fitted;
    for (const BuildingFitParameterEntry& parameter : spec.parameters) {
      fitted.push_back(parameter.name);
    }
    spec.priors = ReadPriorEntries(reader, priors, "priors", false, fitted);
  }
  if (const YAML::Node channels = root["channels"]) {
    reader.RequireSequence(channels, "channels");
    for (std::size_t i = 0; i < channels.size(); ++i) {
      spec.channels.push_back(reader.ReadString(channels[i], IndexPath("channels", i)));
      spec.channel_where.push_back(reader.Locate(channels[i]));
    }
  }
  if (const YAML::Node band = root["band"]) {
    reader.RequireSequence(band, "band");
    if (band.size() != 2) reader.Fail(band, "band", "expected [low, high] (1/time)");
    spec.band_low = reader.ReadNumber(band[0], "band");
    spec.band_high = reader.ReadNumber(band[1], "band");
    if (!(*spec.band_low >= 0.0 && *spec.band_high > *spec.band_low)) {
      reader.Fail(band, "band", "expected 0 <= low < high");
    }
  }
  if (const YAML::Node pause = root["pause"]) {
    spec.pause = reader.ReadNumber(pause, "pause");
    if (!(spec.pause > 0.0)) reader.Fail(pause, "pause", "must be > 0");
  }
  if (const YAML::Node substeps = root["substeps"]) {
    spec.substeps = reader.ReadInteger(substeps, "substeps");
    if (spec.substeps < 1) reader.Fail(substeps, "substeps", "must be >= 1");
  }
  return spec;
}

}  // namespace isolab::model
