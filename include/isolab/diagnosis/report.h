// The diagnosis report, built once here and rendered by the command line and the Python module
// alike: Markdown for a reader, JSON for programs (Python's isolab.diagnose returns it parsed), a
// terminal summary, and the residual series as CSV for the plot. Its first lines say whether the
// residual is noise, and when it is not, that no effect named explains it; then the effects with
// their evidence, the candidates weighed, identifiability, the loops test by test and where the
// residual lies.
#pragma once

#include <string>
#include <vector>

#include "isolab/diagnosis/diagnose.h"

namespace isolab::diagnosis {

struct ReportContext {
  std::vector<std::string> data_files;
  std::string base_file;
  std::string model_file;                // where the final model was written ("" if nowhere)
  std::string residual_file, plot_file;  // "" if not written
  unsigned seed = 1;
  std::string force_unit = "kN", length_unit = "mm";
  std::vector<std::string> notes;  // more lines for the report's head (e.g. model writing notes)
};

// Per test, means over its half-cycles between reversals, measured and by the base and final
// models, and the test's e^2 under each.
struct TestLoops {
  std::string name;
  double amplitude = 0.0, period = 0.0;
  double energy_measured = 0.0, energy_base = 0.0, energy_final = 0.0;
  double secant_measured = 0.0, secant_base = 0.0, secant_final = 0.0;
  double e2_base = 0.0, e2_final = 0.0;
};

struct DiagnosisReport {
  Diagnosis diagnosis;
  ReportContext context;
  std::size_t tests = 0;
  bool one_specimen = false;
  std::vector<std::string> head;  // the first lines: verdict, what the effects do and do not do
  std::vector<TestLoops> loops;
  ResidualVerdict base_residual;  // the base model's residual, in the same cells as the verdict
  // The residual series: per test and sample, the state and the forces (for the CSV and plot).
  struct Series {
    std::vector<std::string> test;
    std::vector<double> time, displacement, velocity, measured, base, final, noise;
  } series;
};

DiagnosisReport BuildReport(const Diagnosis& diagnosis, const identification::FitData& data,
                            ReportContext context);

std::string RenderMarkdown(const DiagnosisReport& report);
std::string RenderJson(const DiagnosisReport& report);
// The command line's summary: the head, the e^2 of the base and the floor, the steps and why
// the search stopped.
std::string RenderSummary(const DiagnosisReport& report);
// test,time,displacement,velocity,measured,base,final,residual,noise with a "# units:" line.
std::string RenderResidualCsv(const DiagnosisReport& report);

}  // namespace isolab::diagnosis
