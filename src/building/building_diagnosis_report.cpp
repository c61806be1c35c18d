#include "isolab/building/building_diagnosis_report.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

namespace isolab::building {
namespace {

// "ica50: d1 0.113, a6 0.185; lac100: ..."
std::string ChannelList(const BuildingFitResult& fit) {
  std::string text, motion;
  for (const ChannelFit& c : fit.channels) {
    const bool next = c.motion != motion;
    text += fmt::format("{}{}{} {:.3f}", text.empty() ? "" : (next ? "; " : ", "),
                        next ? c.motion + ": " : "", c.channel, c.nrmse);
    motion = c.motion;
  }
  return text;
}

// The building's part of the story, for the head of the report.
std::vector<std::string> BuildingLines(const BuildingDiagnosis& result) {
  std::vector<std::string> lines;
  lines.push_back(fmt::format(
      "The building, fitted by output error with its own isolation ({} parameters): mean NRMSE^2 "
      "{:.4g} -> {:.4g}; NRMSE per channel: {}",
      result.base_parameters, result.base.objective_start, result.base.objective,
      ChannelList(result.base)));
  lines.push_back(
      "The isolator's loops below are reconstructed per bearing from the measured absolute "
      "accelerations and the fitted building's masses, against the slab's measured "
      "displacement");
  if (result.refit) {
    lines.push_back(
        fmt::format("Refitted with the diagnosed isolation ({} parameters): NRMSE per channel: {}",
                    result.refit_parameters, ChannelList(*result.refit)));
  }
  lines.push_back(fmt::format("Building: {}", result.conclusion));
  return lines;
}

nlohmann::json DiagnosedFitJson(const BuildingFitResult& fit) {
  nlohmann::json json;
  json["objective_start"] = fit.objective_start;
  json["objective"] = fit.objective;
  json["effective_samples"] = fit.effective_samples;
  for (const FittedParameter& p : fit.parameters) {
    json["parameters"].push_back({{"name", p.name}, {"value", p.value}, {"sigma", p.sigma}});
  }
  for (const ChannelFit& c : fit.channels) {
    json["channels"].push_back({{"motion", c.motion},
                                {"channel", c.channel},
                                {"nrmse_start", c.nrmse_start},
                                {"nrmse", c.nrmse}});
  }
  return json;
}

}  // namespace

diagnosis::DiagnosisReport BuildBuildingReport(const BuildingDiagnosis& result,
                                               diagnosis::ReportContext context) {
  std::vector<std::string> notes = BuildingLines(result);
  notes.insert(notes.end(), context.notes.begin(), context.notes.end());
  context.notes = std::move(notes);
  return diagnosis::BuildReport(result.isolator, result.loops, std::move(context));
}

std::string BuildingDiagnosisJson(const BuildingDiagnosis& result,
                                  const diagnosis::DiagnosisReport& report) {
  nlohmann::json json = nlohmann::json::parse(diagnosis::RenderJson(report));
  json["building"] = {
      {"base", DiagnosedFitJson(result.base)}, {"added", result.added},
      {"confirmed", result.confirmed},         {"bic_base", result.bic_base},
      {"bic_refit", result.bic_refit},         {"effective_samples", result.samples},
      {"conclusion", result.conclusion}};
  if (result.refit) json["building"]["refit"] = DiagnosedFitJson(*result.refit);
  return json.dump(2);
}

}  // namespace isolab::building
