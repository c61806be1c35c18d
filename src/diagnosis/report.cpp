#include "isolab/diagnosis/report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

namespace isolab::diagnosis {
namespace {

using identification::FitData;
using nlohmann::json;

// "+4.2 %" for model against measured, "-" where the measured value is zero.
std::string Deviation(double model, double measured) {
  return measured != 0.0 ? fmt::format("{:+.1f} %", 100 * (model / measured - 1)) : "-";
}

std::string ComponentsText(const FittedModel& model) {
  std::string text;
  for (std::size_t c = 0; c < model.components.size(); ++c) {
    const auto type = model.components[c].type;
    const auto keys = hysteresis::ParameterKeys(type, hysteresis::ParameterForm::kMathematical);
    text += fmt::format("{}{} ({}:", c == 0 ? "" : "; ", model.components[c].name,
                        hysteresis::LawName(type));
    for (std::size_t k = 0; k < keys.size(); ++k) {
      text += fmt::format(" {}={:.5g}", keys[k], model.fit.mathematical[c][k]);
    }
    text += ")";
  }
  return text;
}

std::string EffectList(const Diagnosis& d) {
  std::string list;
  for (const DiagnosisStep& step : d.steps) {
    list += fmt::format("{}{}", list.empty() ? "" : ", then ", EffectName(step.effect));
  }
  return list;
}

// "e^2 = 15.1 % (sum over 12 tests; 1.26 % per test on average, 0.5 to 3.1 %)".
std::string E2Text(const identification::FitError& error) {
  if (error.per_test.size() < 2) return fmt::format("e^2 = {:.4g} %", 100 * error.total);
  const auto [low, high] = std::minmax_element(error.per_test.begin(), error.per_test.end());
  return fmt::format(
      "e^2 = {:.4g} % (the sum over {} tests; {:.4g} % per test on average, "
      "{:.3g} to {:.3g} %)",
      100 * error.total, error.per_test.size(), 100 * error.Mean(), 100 * *low, 100 * *high);
}

json ParametersJson(hysteresis::LawType type, const std::vector<double>& values) {
  json parameters = json::object();
  const auto keys = hysteresis::ParameterKeys(type, hysteresis::ParameterForm::kMathematical);
  for (std::size_t k = 0; k < keys.size(); ++k) parameters[std::string(keys[k])] = values[k];
  return parameters;
}

json ModelJson(const FittedModel& model) {
  json out = {{"e2", model.fit.error.total},
              {"e2_mean", model.fit.error.Mean()},
              {"e2_per_test", model.fit.error.per_test},
              {"bic", model.bic},
              {"parameters", model.parameters},
              {"effective_samples", model.effective_samples},
              {"evaluations", model.fit.evaluations},
              {"fit_stop", model.fit.stop_reason},
              {"dropped", model.dropped},
              {"components", json::array()}};
  for (std::size_t c = 0; c < model.components.size(); ++c) {
    out["components"].push_back(
        {{"name", model.components[c].name},
         {"type", hysteresis::LawName(model.components[c].type)},
         {"parameters", ParametersJson(model.components[c].type, model.fit.mathematical[c])}});
  }
  return out;
}

json CandidateJson(const Candidate& c) {
  json out = {{"effect", EffectName(c.evidence.effect)},
              {"statistic", c.evidence.statistic},
              {"value", c.evidence.value},
              {"threshold", c.evidence.threshold},
              {"supported", c.evidence.Supported()},
              {"finding", c.evidence.finding},
              {"refitted", c.refitted},
              {"supporting", json::object()}};
  for (const auto& s : c.evidence.supporting) out["supporting"][s.name] = s.value;
  if (c.refitted) {
    out["e2_after"] = c.e2;
    out["bic_after"] = c.bic;
    out["bic_before"] = c.bic_current;
    out["bic_gain"] = c.Gain();
    out["refused"] = c.refused;
  }
  return out;
}

json TableJson(const ResidualTable& table) {
  return {{"title", table.title}, {"rows", table.rows}, {"columns", table.columns},
          {"rms", table.rms},     {"mean", table.mean}, {"samples", table.samples}};
}

json VerdictJson(const ResidualVerdict& v) {
  json out = {{"kind", VerdictName(v.kind)},
              {"headline", v.headline},
              {"e2", v.e2},
              {"noise_floor_e2", v.floor},
              {"ratio", v.ratio},
              {"correlation_time", v.correlation_time},
              {"whiteness", v.whiteness},
              {"state_share", v.state_share},
              {"where", v.where},
              {"tables", json::array()}};
  for (const ResidualTable& t : v.tables) out["tables"].push_back(TableJson(t));
  return out;
}

json IdentifiabilityJson(const identification::Identifiability& id,
                         const std::vector<identification::ComponentSpec>& components) {
  json out = {{"findings", id.Findings()},   {"singular", id.singular},
              {"unseen", id.unseen},         {"device_peak_force", id.device_peak_force},
              {"components", json::array()}, {"cancelling", json::array()},
              {"at_bounds", json::array()},  {"correlated", json::array()}};
  for (const auto& c : id.components) {
    out["components"].push_back({{"name", c.name},
                                 {"rms_force", c.rms_force},
                                 {"peak_force", c.peak_force},
                                 {"secant", c.secant}});
  }
  for (const auto& p : id.cancelling) {
    out["cancelling"].push_back({{"a", components[p.a].name},
                                 {"b", components[p.b].name},
                                 {"opposition", p.opposition},
                                 {"sum_share", p.sum_share}});
  }
  for (const auto& p : id.at_bounds) {
    out["at_bounds"].push_back({{"name", p.name}, {"value", p.value}, {"where", p.where}});
  }
  for (const auto& p : id.correlated) {
    out["correlated"].push_back({{"a", p.a}, {"b", p.b}, {"correlation", p.correlation}});
  }
  return out;
}

// Per test, means over its half-cycles.
std::vector<TestLoops> Loops(const Discrepancy& base, const Discrepancy& final_fit,
                             const Diagnosis& d) {
  std::map<int, std::pair<TestLoops, int>> rows;
  for (std::size_t k = 0; k < base.cycles.size(); ++k) {
    const CycleRecord& b = base.cycles[k];
    const CycleRecord& f = final_fit.cycles[k];
    auto& [row, count] = rows[b.test];
    row.name = base.data->tests[b.test].name;
    row.amplitude += b.amplitude;
    row.period += b.period;
    row.energy_measured += b.measured.energy;
    row.energy_base += b.modelled.energy;
    row.energy_final += f.modelled.energy;
    row.secant_measured += b.measured.secant;
    row.secant_base += b.modelled.secant;
    row.secant_final += f.modelled.secant;
    ++count;
  }
  std::vector<TestLoops> result;
  for (auto& [test, entry] : rows) {
    TestLoops row = entry.first;
    const double n = entry.second;
    for (double* x :
         {&row.amplitude, &row.period, &row.energy_measured, &row.energy_base, &row.energy_final,
          &row.secant_measured, &row.secant_base, &row.secant_final}) {
      *x /= n;
    }
    row.e2_base = d.base.fit.error.per_test[static_cast<std::size_t>(test)];
    row.e2_final = d.final_model.fit.error.per_test[static_cast<std::size_t>(test)];
    result.push_back(row);
  }
  return result;
}

// Where the two reads of a test's noise disagree (discrepancy.h), what that does to the floor;
// empty where every test's reads agree.
std::string UncertainFloorText(const Diagnosis& d) {
  int count = 0;
  double apart = 1.0;
  for (const NoiseEstimate& n : d.noise) {
    if (!n.uncertain) continue;
    ++count;
    apart = std::max(apart, std::max(n.rest_sigma, n.band_sigma) /
                                std::max(std::min(n.rest_sigma, n.band_sigma), 1e-300));
  }
  if (count == 0) return "";
  return fmt::format(
      "the noise floor is uncertain: for {} of {} tests the force's noise read at rest and read "
      "above the response differ by more than a factor of {:g} (up to {:.3g} times: the device's "
      "own noise while it moves, such as stick-slip chatter, or noise inside its band); the floor "
      "and the gates use the larger",
      count, d.noise.size(), kNoiseReadsAgree, apart);
}

std::vector<std::string> Head(const Diagnosis& d, const ReportContext& context) {
  std::vector<std::string> head;
  head.push_back("Verdict: " + d.verdict.headline + ".");
  const bool structured = d.verdict.Structured();
  if (d.steps.empty()) {
    head.push_back(structured ? "No effect in the catalogue explains it: none was named."
                              : "No effect is missing: the base model leaves what noise leaves.");
  } else if (structured) {
    head.push_back(fmt::format(
        "Added: {} (e^2 {:.4g} % -> {:.4g} %). They do not explain what remains, and no other "
        "effect in the catalogue does: read them as a better fit, not as the explanation.",
        EffectList(d), 100 * d.base.fit.error.total, 100 * d.final_model.fit.error.total));
  } else {
    head.push_back(
        fmt::format("Named: {}; with {} the residual is noise (e^2 {:.4g} % -> "
                    "{:.4g} %).",
                    EffectList(d), d.steps.size() == 1 ? "it" : "them",
                    100 * d.base.fit.error.total, 100 * d.final_model.fit.error.total));
  }
  if (structured) {
    for (const std::string& where : d.verdict.where) head.push_back("Where: " + where + ".");
  }
  for (const std::string& finding : d.identifiability.Findings()) {
    head.push_back("Identifiability: " + finding + ".");
  }
  if (const std::string uncertain = UncertainFloorText(d); !uncertain.empty()) {
    head.push_back("Note: " + uncertain + ".");
  }
  for (const std::string& note : d.final_model.dropped) head.push_back("Note: " + note + ".");
  for (const std::string& note : context.notes) head.push_back("Note: " + note + ".");
  return head;
}

std::string NoiseText(const Diagnosis& d) {
  int rest = 0, band = 0, other = 0, uncertain = 0;
  for (const NoiseEstimate& n : d.noise) {
    rest += n.source == NoiseEstimate::Source::kRest;
    band += n.source == NoiseEstimate::Source::kBand;
    other += n.source == NoiseEstimate::Source::kNone;
    uncertain += n.uncertain;
  }
  std::string text;
  if (band > 0) text += fmt::format("in the band above the response for {} tests", band);
  if (rest > 0)
    text += fmt::format("{}from samples at rest for {}", text.empty() ? "" : ", ", rest);
  if (other > 0) {
    text += fmt::format("{}from second differences for {} (no band above the response)",
                        text.empty() ? "" : ", ", other);
  }
  if (uncertain > 0) {
    text += fmt::format(" ({} uncertain: the larger of the two reads)", uncertain);
  }
  return text;
}

std::string TableMarkdown(const ResidualTable& table, const std::string& model) {
  std::string md = fmt::format("| {} | {} |", model, fmt::join(table.columns, " | "));
  md += "\n|---|";
  for (std::size_t c = 0; c < table.columns.size(); ++c) md += "---|";
  md += "\n";
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    md += fmt::format("| {} |", table.rows[r]);
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      md += table.samples[r][c] > 0
                ? fmt::format(" {:.2f} ({:+.2f}) |", table.rms[r][c], table.mean[r][c])
                : " - |";
    }
    md += "\n";
  }
  return md;
}

}  // namespace

DiagnosisReport BuildReport(const Diagnosis& diagnosis, const FitData& data,
                            ReportContext context) {
  DiagnosisReport report;
  report.diagnosis = diagnosis;
  report.tests = data.tests.size();
  report.one_specimen = data.one_specimen;
  report.head = Head(diagnosis, context);
  report.context = std::move(context);
  const Discrepancy base =
      Discrepancy::Of(AssemblyOf(diagnosis.base, data), data, &diagnosis.noise);
  const Discrepancy final_fit =
      Discrepancy::Of(AssemblyOf(diagnosis.final_model, data), data, &diagnosis.noise);
  report.loops = Loops(base, final_fit, diagnosis);
  report.base_residual = JudgeResidual(base, diagnosis.base.fit.error.total, diagnosis.noise_floor);
  auto& s = report.series;
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const auto& test = data.tests[i];
    for (const auto& span : data.fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k) {
        s.test.push_back(test.name);
        s.time.push_back(test.time[k]);
        s.displacement.push_back(test.displacement[k]);
        s.velocity.push_back(base.velocity[i][k]);
        s.measured.push_back(test.force[k]);
        s.base.push_back(base.model_force[i][k]);
        s.final.push_back(final_fit.model_force[i][k]);
        s.noise.push_back(diagnosis.noise[i].sigma);
      }
    }
  }
  return report;
}

std::string RenderJson(const DiagnosisReport& report) {
  const Diagnosis& d = report.diagnosis;
  const ReportContext& c = report.context;
  json out;
  out["head"] = report.head;
  out["data"] = c.data_files;
  out["base_file"] = c.base_file;
  out["seed"] = c.seed;
  out["units"] = {{"force", c.force_unit}, {"length", c.length_unit}};
  out["tests"] = report.tests;
  out["one_specimen"] = report.one_specimen;
  out["samples"] = d.samples;
  out["noise_floor_e2"] = d.noise_floor;
  out["noise"] = json::array();
  for (const NoiseEstimate& n : d.noise) {
    json entry = {{"sigma", n.sigma}, {"source", n.Describe()}, {"uncertain", n.uncertain}};
    if (n.rest_samples > 0) entry["rest_sigma"] = n.rest_sigma;
    if (n.band_low > 0.0) entry["band_sigma"] = n.band_sigma;
    out["noise"].push_back(entry);
  }
  out["base"] = ModelJson(d.base);
  out["steps"] = json::array();
  for (const DiagnosisStep& step : d.steps) {
    json s = {{"effect", EffectName(step.effect)},
              {"explanation", EffectExplanation(step.effect)},
              {"evidence", CandidateJson({step.evidence})},
              {"e2_before", step.e2_before},
              {"e2_after", step.e2_after},
              {"bic_before", step.bic_before},
              {"bic_after", step.bic_after},
              {"added",
               {{"name", step.added.name},
                {"type", hysteresis::LawName(step.added.type)},
                {"parameters", ParametersJson(step.added.type, step.added_parameters)}}},
              {"candidates", json::array()}};
    for (const Candidate& candidate : step.candidates) {
      s["candidates"].push_back(CandidateJson(candidate));
    }
    out["steps"].push_back(s);
  }
  out["effects"] = json::array();
  for (const DiagnosisStep& step : d.steps) out["effects"].push_back(EffectName(step.effect));
  if (d.steps.empty()) out["effects"].push_back("none");
  out["final"] = ModelJson(d.final_model);
  out["final_model_file"] = c.model_file;
  out["residual_file"] = c.residual_file;
  out["plot_file"] = c.plot_file;
  out["stop"] = StopReasonName(d.stop);
  out["stop_reason"] = d.stop_reason;
  out["last_candidates"] = json::array();
  for (const Candidate& candidate : d.last_candidates) {
    out["last_candidates"].push_back(CandidateJson(candidate));
  }
  out["verdict"] = VerdictJson(d.verdict);
  out["base_residual"] = VerdictJson(report.base_residual);
  out["identifiability"] = IdentifiabilityJson(d.identifiability, d.final_model.components);
  out["loops"] = json::array();
  for (const TestLoops& row : report.loops) {
    out["loops"].push_back({{"test", row.name},
                            {"amplitude", row.amplitude},
                            {"period", row.period},
                            {"energy", {row.energy_measured, row.energy_base, row.energy_final}},
                            {"secant", {row.secant_measured, row.secant_base, row.secant_final}},
                            {"e2", {row.e2_base, row.e2_final}}});
  }
  out["seconds"] = d.seconds;
  return out.dump(2) + "\n";
}

std::string RenderMarkdown(const DiagnosisReport& report) {
  const Diagnosis& d = report.diagnosis;
  const ReportContext& context = report.context;
  const std::string force = context.force_unit, length = context.length_unit;
  std::string md = fmt::format("# isolab diagnose: {}\n\n", fmt::join(context.data_files, ", "));
  md += fmt::format("**{}**\n\n", report.head.front());
  for (std::size_t k = 1; k < report.head.size(); ++k) md += "- " + report.head[k] + "\n";
  md += fmt::format(
      "\n{} tests ({}), {} samples. Base model ({}): {}.\n\n"
      "Base fit: **{}**. Noise floor (the e^2 that measurement noise alone leaves, read {}): "
      "{:.4g} %. The final residual counts as {:.0f} independent samples of {} (correlation time "
      "{:.3g} s).\n\n",
      report.tests,
      report.one_specimen ? "one specimen tested in this order, each test starting from the "
                            "state the previous one left"
                          : "independent specimens, each simulated from rest",
      d.samples, context.base_file, ComponentsText(d.base), E2Text(d.base.fit.error), NoiseText(d),
      100 * d.noise_floor, d.final_model.effective_samples, d.samples, d.verdict.correlation_time);

  md += "## Finding\n\n";
  if (d.steps.empty()) {
    md += "**none**: no effect in the catalogue is named. ";
  } else {
    md +=
        "| step | effect | evidence (threshold) | e^2 before | e^2 after | BIC before | BIC after "
        "| added |\n|---|---|---|---|---|---|---|---|\n";
    for (std::size_t k = 0; k < d.steps.size(); ++k) {
      const auto& s = d.steps[k];
      md += fmt::format(
          "| {} | **{}** | {:.4g} ({:.3g}) | {:.4g} % | {:.4g} % | {:.1f} | {:.1f} | {} ({}) |\n",
          k + 1, EffectName(s.effect), s.evidence.value, s.evidence.threshold, 100 * s.e2_before,
          100 * s.e2_after, s.bic_before, s.bic_after, s.added.name,
          hysteresis::LawName(s.added.type));
    }
    md += "\n";
  }
  const double final_e2 = d.final_model.fit.error.total;
  md += fmt::format(
      "Final model: {} ({} of the base's, {} the noise floor){}. The search stopped because "
      "{}.\n\n",
      E2Text(d.final_model.fit.error),
      d.base.fit.error.total > 0 ? fmt::format("{:.3g}", final_e2 / d.base.fit.error.total) : "-",
      d.noise_floor > 0 ? fmt::format("{:.2f} x", final_e2 / d.noise_floor) : "above",
      context.model_file.empty() ? "" : fmt::format(", written to `{}`", context.model_file),
      d.stop_reason);

  const auto candidate_table = [&](const std::vector<Candidate>& candidates) {
    std::string t =
        "| effect | statistic | value | threshold | supported | refitted e^2 | BIC gain | "
        "refused |\n|---|---|---|---|---|---|---|---|\n";
    for (const Candidate& c : candidates) {
      t += fmt::format("| {} | {} | {:.4g} | {:.3g} | {} | {} | {} | {} |\n",
                       EffectName(c.evidence.effect), c.evidence.statistic, c.evidence.value,
                       c.evidence.threshold, c.evidence.Supported() ? "yes" : "no",
                       c.refitted ? fmt::format("{:.4g} %", 100 * c.e2) : "-",
                       c.refitted ? fmt::format("{:.1f}", c.Gain()) : "-",
                       c.refused.empty() ? "-" : c.refused);
    }
    return t + "\n";
  };
  for (std::size_t k = 0; k < d.steps.size(); ++k) {
    const auto& s = d.steps[k];
    md += fmt::format("## Step {}: {}\n\n{}\n\n**Evidence.** {}.\n\n", k + 1, EffectName(s.effect),
                      EffectExplanation(s.effect), s.evidence.finding);
    const auto keys =
        hysteresis::ParameterKeys(s.added.type, hysteresis::ParameterForm::kMathematical);
    md += fmt::format("**Added** `{}` ({}):", s.added.name, hysteresis::LawName(s.added.type));
    for (std::size_t p = 0; p < keys.size(); ++p) {
      md += fmt::format(" {} = {:.5g}", keys[p], s.added_parameters[p]);
    }
    md += fmt::format(
        ". e^2 {:.4g} % -> {:.4g} %; BIC {:.1f} -> {:.1f}.\n\nCandidates weighed "
        "(strongest evidence first; each supported one refitted):\n\n",
        100 * s.e2_before, 100 * s.e2_after, s.bic_before, s.bic_after);
    md += candidate_table(s.candidates);
  }
  md += "## What was left\n\nEvidence on the final model's residual:\n\n";
  md += candidate_table(d.last_candidates);

  md +=
      fmt::format("## Identifiability of the final model\n\n{}\n\n", ComponentsText(d.final_model));
  md +=
      "| component | RMS force | peak force | secant stiffness over the tests |\n"
      "|---|---|---|---|\n";
  for (const auto& c : d.identifiability.components) {
    md += fmt::format("| {} | {:.4g} | {:.4g} | {:+.4g} |\n", c.name, c.rms_force, c.peak_force,
                      c.secant);
  }
  md += fmt::format("\nThe device's measured force reaches {:.4g} {}.\n\n",
                    d.identifiability.device_peak_force, force);
  const auto findings = d.identifiability.Findings();
  if (findings.empty()) {
    md +=
        "No cancelling components, no parameter at a bound and no pair correlated beyond "
        "0.95.\n\n";
  } else {
    for (const std::string& f : findings) md += "- " + f + "\n";
    md += "\n";
  }

  md += fmt::format(
      "## Loops, test by test\n\nMean over each test's half-cycles between reversals "
      "(amplitude: half the reversal-to-reversal range; period: twice the duration): energy "
      "dissipated per half-cycle [{f}*{l}] and secant stiffness between the reversals [{f}/{l}], "
      "measured and modelled, and each test's e^2.\n\n"
      "| test | amplitude [{l}] | period | W measured | W base | W final | K measured | K base | "
      "K final | e^2 base | e^2 final |\n|---|---|---|---|---|---|---|---|---|---|---|\n",
      fmt::arg("f", force), fmt::arg("l", length));
  for (const TestLoops& row : report.loops) {
    md += fmt::format(
        "| {} | {:.4g} | {:.3g} | {:.5g} | {:.5g} ({}) | {:.5g} ({}) | {:.4g} | {:.4g} ({}) | "
        "{:.4g} ({}) | {:.3g} % | {:.3g} % |\n",
        row.name, row.amplitude, row.period, row.energy_measured, row.energy_base,
        Deviation(row.energy_base, row.energy_measured), row.energy_final,
        Deviation(row.energy_final, row.energy_measured), row.secant_measured, row.secant_base,
        Deviation(row.secant_base, row.secant_measured), row.secant_final,
        Deviation(row.secant_final, row.secant_measured), 100 * row.e2_base, 100 * row.e2_final);
  }
  md +=
      "\n## Where the residual lies\n\nRMS residual in units of each test's noise (1: the model "
      "misses by no more than noise there), with the mean residual in brackets: a mean far from "
      "0 is a bias the model has there. By direction of motion and |u| / u_a, by direction and "
      "the time since the last reversal (share of the half-cycle), and by loading (u v > 0) and "
      "unloading branch.\n\n";
  for (std::size_t t = 0; t < d.verdict.tables.size(); ++t) {
    md += fmt::format("{}:\n\n", d.verdict.tables[t].title);
    md += TableMarkdown(report.base_residual.tables[t], "base") + "\n";
    md += TableMarkdown(d.verdict.tables[t], "final");
    md += "\n";
  }
  if (!context.residual_file.empty()) {
    md += fmt::format("The residual, sample by sample: `{}`", context.residual_file);
    md +=
        context.plot_file.empty() ? ".\n" : fmt::format("; plotted in `{}`.\n", context.plot_file);
  }
  md += fmt::format("\nSeed {}; {:.1f} s.\n", context.seed, d.seconds);
  return md;
}

std::string RenderSummary(const DiagnosisReport& report) {
  const Diagnosis& d = report.diagnosis;
  std::string out;
  for (const std::string& line : report.head) out += line + "\n";
  out += fmt::format("base {}   noise floor {:.4g} %\n", E2Text(d.base.fit.error),
                     100 * d.noise_floor);
  if (d.steps.empty()) out += "effect: none\n";
  for (std::size_t k = 0; k < d.steps.size(); ++k) {
    const auto& s = d.steps[k];
    out += fmt::format(
        "step {}: {:<32} evidence {:.4g} (threshold {:.3g})   e^2 {:.4g} % -> {:.4g} %\n", k + 1,
        EffectName(s.effect), s.evidence.value, s.evidence.threshold, 100 * s.e2_before,
        100 * s.e2_after);
  }
  out += fmt::format("stopped: {}\n", d.stop_reason);
  return out;
}

std::string RenderResidualCsv(const DiagnosisReport& report) {
  const auto& s = report.series;
  std::string csv = fmt::format("# units: force {}, length {}\n", report.context.force_unit,
                                report.context.length_unit);
  csv += "test,time,displacement,velocity,measured,base,final,residual,noise\n";
  for (std::size_t k = 0; k < s.time.size(); ++k) {
    csv += fmt::format("{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.6g}\n", s.test[k],
                       s.time[k], s.displacement[k], s.velocity[k], s.measured[k], s.base[k],
                       s.final[k], s.measured[k] - s.final[k], s.noise[k]);
  }
  return csv;
}

}  // namespace isolab::diagnosis
