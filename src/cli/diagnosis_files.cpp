#include "diagnosis_files.h"

#include <fmt/format.h>

#include <filesystem>

#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "plot_script.h"

namespace isolab::cli {
namespace {

constexpr const char* kDiagnosisPlot = "plot_diagnosis.py";

void WriteText(const std::string& path, const std::string& text) {
  io::WriteTextFileAtomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace

DiagnosisFiles DiagnosisFiles::Plan(const std::string& out, const std::string& first_data,
                                    bool plot, diagnosis::ReportContext* context) {
  // The stem names files: a folder would leave them hidden in it (DIR/.md, DIR/.json, ...).
  if (!out.empty() &&
      (std::filesystem::path(out).filename().empty() || std::filesystem::is_directory(out))) {
    std::string folder = out;
    while (folder.size() > 1 && folder.back() == '/') folder.pop_back();
    throw InputError({"--out"}, fmt::format("'{}' is a folder; the report's stem names its files, "
                                            "e.g. {}/report for report.md, report.json, ...",
                                            out, folder));
  }
  DiagnosisFiles files;
  files.stem = !out.empty()
                   ? out
                   : std::filesystem::path(first_data).replace_extension().string() + ".diagnosis";
  context->model_file = files.stem + ".model.yaml";
  context->residual_file = files.stem + ".residual.csv";
  files.outputs = {context->model_file, files.stem + ".json", files.stem + ".md",
                   context->residual_file};
  if (plot) files.outputs.push_back(files.stem + ".residual.png");
  // The plot needs Python's matplotlib: without it the report says so and goes on.
  files.plot = plot;
  if (plot) {
    try {
      CheckPlotScript(kDiagnosisPlot);
    } catch (const InputError& error) {
      files.plot = false;
      context->notes.push_back(fmt::format("no residual plot: {}", error.what()));
    }
  }
  if (files.plot) context->plot_file = files.stem + ".residual.png";
  return files;
}

void DiagnosisFiles::Write(const diagnosis::DiagnosisReport& report, const std::string& json,
                           const std::string& plot_title, bool quiet) const {
  WriteText(report.context.residual_file, diagnosis::RenderResidualCsv(report));
  WriteText(stem + ".json", json);
  WriteText(stem + ".md", diagnosis::RenderMarkdown(report));
  if (plot) {
    RunPlotScript(
        kDiagnosisPlot,
        {report.context.residual_file, "-o", report.context.plot_file, "--title", plot_title},
        quiet);
  }
}

std::string DiagnosisFiles::Where(const diagnosis::ReportContext& context) const {
  return fmt::format("report: {}.md, {}.json, {}{}; final model: {}\n", stem, stem,
                     context.residual_file, plot ? ", " + context.plot_file : "",
                     context.model_file.empty() ? "not written" : context.model_file);
}

}  // namespace isolab::cli
