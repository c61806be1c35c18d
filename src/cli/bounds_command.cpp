#include "bounds_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "common_options.h"
#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/model/bounds.h"
#include "isolab/model/model_file.h"
#include "isolab/model/opensees_export.h"

namespace isolab::cli {

void RegisterBoundsCommand(CLI::App& app, BoundsOptions& o) {
  CLI::App* command = app.add_subcommand(
      "bounds",
      "Write a model's nominal, upper-bound and lower-bound models from its property "
      "modification factors (ASCE 7-16 17.2.8.4)");
  command->add_option("model", o.model, "Model file (YAML) with modification factors")->required();
  AddOutputOption(
      command, &o.output,
      "Folder to write <model>_nominal.yaml, _upper.yaml and _lower.yaml to (made if missing)")
      ->required();
  command->add_flag("--opensees", o.opensees,
                    "Also write each bound's bearings as OpenSees elements, <model>_<bound>.tcl "
                    "(docs/bearings.md names the elements)");
  AddQuietFlag(command, &o.quiet, "Print nothing");
}

namespace {

// How an OpenSees export's heading (its first line, after "# ") ends: the mark of a file `isolab
// bounds` wrote, as kBoundModelHeader is the bound models'.
constexpr std::string_view kExportMark = "(isolab bounds)";

}  // namespace

void RunBoundsCommand(const BoundsOptions& o, std::ostream& out) {
  const model::ModelFile model = model::LoadModelFile(o.model);
  const std::filesystem::path folder(o.output);
  if (std::filesystem::exists(folder) && !std::filesystem::is_directory(folder)) {
    throw InputError({"--output"}, fmt::format("'{}' is not a folder", o.output));
  }
  const model::BoundModels bounds = model::MakeBoundModels(model);
  const std::string stem = std::filesystem::path(o.model).stem().string();
  // Every file's text first, so that a bound the export refuses writes nothing.
  std::vector<std::string> paths, texts;
  for (const model::BoundModel& bound : bounds.models) {
    const std::string path = (folder / (stem + "_" + bound.bound + ".yaml")).string();
    paths.push_back(path);
    texts.push_back(bound.text);
    if (!o.opensees) continue;
    const model::OpenSeesExport exported = model::ExportToOpenSees(
        model::LoadModelText(bound.text, path),
        fmt::format("{} bound of {} {}", bound.bound, o.model, kExportMark));
    if (!exported.refused.empty()) {
      throw InputError({o.model}, fmt::format("--opensees: the {} bound's bearings cannot be "
                                              "exported to OpenSees: {}",
                                              bound.bound, exported.refused));
    }
    paths.push_back((folder / (stem + "_" + bound.bound + ".tcl")).string());
    texts.push_back(exported.tcl);
  }
  // Made as `design` makes its folder, once the models are known to be right.
  std::error_code error;
  if (!std::filesystem::exists(folder)) std::filesystem::create_directories(folder, error);
  if (error) {
    throw InputError({"--output"},
                     fmt::format("cannot make the folder '{}': {}", o.output, error.message()));
  }
  for (const std::string& path : paths) {
    io::CheckOutputPath(path);
    // Only a file an earlier `isolab bounds` wrote is replaced (its models' first line, or an
    // OpenSees export's, says so).
    std::ifstream existing(path);
    std::string first;
    if (!existing || !std::getline(existing, first)) continue;  // not there (or empty)
    const bool ours = first.starts_with(model::kBoundModelHeader) ||
                      (first.starts_with("# ") && first.ends_with(kExportMark));
    if (!ours) {
      throw InputError({path},
                       "exists, and isolab bounds did not write it: choose another "
                       "folder (-o), or move the file away");
    }
  }
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const std::string& text = texts[i];
    io::WriteTextFileAtomically(paths[i], [&text](std::ostream& file) { file << text; });
  }
  if (o.quiet) return;
  fmt::print(out, "{}: property modification factors (ASCE 7-16 17.2.8.4)\n", o.model);
  fmt::print(out, "{:<12} {:<12} {:<8} {:>10} {:>10} {:>14} {:>14} {:>14}\n", "bearing",
             "component", "property", "lambda_min", "lambda_max", "lower", "nominal", "upper");
  for (const model::BoundProperty& p : bounds.properties) {
    fmt::print(out, "{:<12} {:<12} {:<8} {:>10.4g} {:>10.4g} {:>14} {:>14} {:>14}\n", p.bearing,
               p.component, p.key, p.lambda.min, p.lambda.max, p.lower, p.nominal, p.upper);
  }
  for (const std::string& path : paths) fmt::print(out, "wrote {}\n", path);
}

}  // namespace isolab::cli
