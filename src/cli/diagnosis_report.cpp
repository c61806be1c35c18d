#include "diagnosis_report.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <map>

namespace isolab::cli {
namespace {

using diagnosis::Candidate;
using diagnosis::Diagnosis;
using diagnosis::Discrepancy;
using diagnosis::EffectName;
using identification::FitData;

// "+4.2 %" for model against measured, "-" where the measured value is zero.
std::string Deviation(double model, double measured) {
  return measured != 0.0 ? fmt::format("{:+.1f} %", 100 * (model / measured - 1)) : "-";
}

std::string ComponentsText(const diagnosis::FittedModel& model) {
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

nlohmann::json ParametersJson(hysteresis::LawType type, const std::vector<double>& values) {
  nlohmann::json json;
  const auto keys = hysteresis::ParameterKeys(type, hysteresis::ParameterForm::kMathematical);
  for (std::size_t k = 0; k < keys.size(); ++k) json[std::string(keys[k])] = values[k];
  return json;
}

nlohmann::json ModelJson(const diagnosis::FittedModel& model) {
  nlohmann::json json = {{"e2", model.fit.error.total},
                         {"bic", model.bic},
                         {"parameters", model.parameters},
                         {"components", nlohmann::json::array()}};
  for (std::size_t c = 0; c < model.components.size(); ++c) {
    json["components"].push_back(
        {{"name", model.components[c].name},
         {"type", hysteresis::LawName(model.components[c].type)},
         {"parameters", ParametersJson(model.components[c].type, model.fit.mathematical[c])}});
  }
  return json;
}

nlohmann::json CandidateJson(const Candidate& c) {
  nlohmann::json json = {{"effect", EffectName(c.evidence.effect)},
                         {"statistic", c.evidence.statistic},
                         {"value", c.evidence.value},
                         {"threshold", c.evidence.threshold},
                         {"supported", c.evidence.Supported()},
                         {"finding", c.evidence.finding},
                         {"refitted", c.refitted}};
  for (const auto& s : c.evidence.supporting) json["supporting"][s.name] = s.value;
  if (c.refitted) {
    json["e2_after"] = c.e2;
    json["bic_after"] = c.bic;
    json["bic_before"] = c.bic_current;
  }
  return json;
}

// Per test, mean over its cycles: amplitude, period, energy and secant stiffness, measured and
// by a model.
struct TestRow {
  std::string name;
  double amplitude = 0, period = 0, energy_measured = 0, energy_model = 0, secant_measured = 0,
         secant_model = 0;
};
std::vector<TestRow> TestRows(const Discrepancy& d) {
  std::map<int, std::pair<TestRow, int>> rows;
  for (const auto& c : d.cycles) {
    auto& [row, count] = rows[c.test];
    row.name = d.data->tests[c.test].name;
    row.amplitude += c.amplitude;
    row.period += c.period;
    row.energy_measured += c.measured.energy;
    row.energy_model += c.modelled.energy;
    row.secant_measured += c.measured.secant;
    row.secant_model += c.modelled.secant;
    ++count;
  }
  std::vector<TestRow> result;
  for (auto& [test, entry] : rows) {
    TestRow row = entry.first;
    const double n = entry.second;
    for (double* x : {&row.amplitude, &row.period, &row.energy_measured, &row.energy_model,
                      &row.secant_measured, &row.secant_model}) {
      *x /= n;
    }
    result.push_back(row);
  }
  return result;
}

// RMS residual in four bands of |u| / u_a, loading (u v > 0) and unloading, in units of the
// estimated noise: 1 means the model misses by no more than noise there.
constexpr int kBands = 4;
std::array<double, 2 * kBands> ResidualBands(const Discrepancy& d) {
  std::array<double, 2 * kBands> sum{}, count{};
  for (std::size_t i = 0; i < d.data->tests.size(); ++i) {
    const auto& test = d.data->tests[i];
    double amplitude = 0.0;
    for (const auto& span : d.data->fitted[i]) {
      amplitude = std::max(amplitude, identification::SpanAmplitude(test.displacement, span));
    }
    const double noise = d.force_noise[i] > 0.0 ? d.force_noise[i] : 1.0;
    for (const auto& span : d.data->fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k) {
        const double u = test.displacement[k];
        const int band = std::min(kBands - 1, static_cast<int>(kBands * std::abs(u) / amplitude));
        const int slot = band + (u * d.velocity[i][k] > 0.0 ? 0 : kBands);
        sum[slot] += std::pow((test.force[k] - d.model_force[i][k]) / noise, 2);
        count[slot] += 1.0;
      }
    }
  }
  for (int b = 0; b < 2 * kBands; ++b) sum[b] = count[b] > 0 ? std::sqrt(sum[b] / count[b]) : 0.0;
  return sum;
}

}  // namespace

nlohmann::json DiagnosisJson(const Diagnosis& d, const FitData& data,
                             const DiagnosisContext& context) {
  nlohmann::json json;
  json["data"] = context.data_files;
  json["base_file"] = context.base_file;
  json["seed"] = context.seed;
  json["units"] = {{"force", context.units.force()}, {"length", context.units.length()}};
  json["tests"] = data.tests.size();
  json["one_specimen"] = data.one_specimen;
  json["samples"] = d.samples;
  json["noise_floor_e2"] = d.noise_floor;
  json["base"] = ModelJson(d.base);
  json["steps"] = nlohmann::json::array();
  for (const auto& step : d.steps) {
    nlohmann::json s = {{"effect", EffectName(step.effect)},
                        {"explanation", diagnosis::EffectExplanation(step.effect)},
                        {"evidence", CandidateJson({step.evidence})},
                        {"e2_before", step.e2_before},
                        {"e2_after", step.e2_after},
                        {"bic_before", step.bic_before},
                        {"bic_after", step.bic_after},
                        {"added",
                         {{"name", step.added.name},
                          {"type", hysteresis::LawName(step.added.type)},
                          {"parameters", ParametersJson(step.added.type, step.added_parameters)}}},
                        {"candidates", nlohmann::json::array()}};
    for (const Candidate& c : step.candidates) s["candidates"].push_back(CandidateJson(c));
    json["steps"].push_back(s);
  }
  json["effects"] = nlohmann::json::array();
  for (const auto& step : d.steps) json["effects"].push_back(EffectName(step.effect));
  if (d.steps.empty()) json["effects"].push_back("none");
  json["final"] = ModelJson(d.final_model);
  json["final_model_file"] = context.model_file;
  json["stop_reason"] = d.stop_reason;
  json["last_candidates"] = nlohmann::json::array();
  for (const Candidate& c : d.last_candidates) json["last_candidates"].push_back(CandidateJson(c));
  json["seconds"] = d.seconds;
  return json;
}

std::string DiagnosisMarkdown(const Diagnosis& d, const FitData& data,
                              const DiagnosisContext& context) {
  const std::string force = context.units.force(), length = context.units.length();
  std::string md = fmt::format("# isolab diagnose: {}\n\n", fmt::join(context.data_files, ", "));
  md += fmt::format(
      "{} tests ({}), {} samples. Base model ({}): {}.\n\n"
      "Base fit: **e^2 = {:.4g} %**. Noise floor (the e^2 that measurement noise alone leaves, "
      "estimated from the data's second differences): {:.4g} %.\n\n",
      data.tests.size(),
      data.one_specimen ? "one specimen tested in this order, each test starting from the state "
                          "the previous one left"
                        : "independent specimens, each simulated from rest",
      d.samples, context.base_file, ComponentsText(d.base), 100 * d.base.fit.error.total,
      100 * d.noise_floor);

  md += "## Finding\n\n";
  if (d.steps.empty()) {
    md += "**none**: no effect in the catalogue is supported by the data. ";
  } else {
    md +=
        "| step | effect | evidence (threshold) | e^2 before | e^2 after | BIC before | BIC after "
        "| added |\n|---|---|---|---|---|---|---|---|\n";
    for (std::size_t k = 0; k < d.steps.size(); ++k) {
      const auto& s = d.steps[k];
      md += fmt::format(
          "| {} | **{}** | {:.4g} ({:.3g}) | {:.4g} % | {:.4g} % | {:.1f} | {:.1f} | "
          "{} ({}) |\n",
          k + 1, EffectName(s.effect), s.evidence.value, s.evidence.threshold, 100 * s.e2_before,
          100 * s.e2_after, s.bic_before, s.bic_after, s.added.name,
          hysteresis::LawName(s.added.type));
    }
    md += "\n";
  }
  const double final_e2 = d.final_model.fit.error.total;
  md += fmt::format(
      "Final model: e^2 = {:.4g} % ({} of the base's, {} the noise floor), written to `{}`. The "
      "search stopped because {}.\n\n",
      100 * final_e2,
      d.base.fit.error.total > 0 ? fmt::format("{:.3g}", final_e2 / d.base.fit.error.total) : "-",
      d.noise_floor > 0 ? fmt::format("{:.2f} x", final_e2 / d.noise_floor) : "above",
      context.model_file, d.stop_reason);

  const auto candidate_table = [&](const std::vector<Candidate>& candidates) {
    std::string t =
        "| effect | statistic | value | threshold | supported | refitted e^2 | BIC gain |\n"
        "|---|---|---|---|---|---|---|\n";
    for (const Candidate& c : candidates) {
      t += fmt::format("| {} | {} | {:.4g} | {:.3g} | {} | {} | {} |\n",
                       EffectName(c.evidence.effect), c.evidence.statistic, c.evidence.value,
                       c.evidence.threshold, c.evidence.Supported() ? "yes" : "no",
                       c.refitted ? fmt::format("{:.4g} %", 100 * c.e2) : "-",
                       c.refitted ? fmt::format("{:.1f}", c.bic_current - c.bic) : "-");
    }
    return t + "\n";
  };
  for (std::size_t k = 0; k < d.steps.size(); ++k) {
    const auto& s = d.steps[k];
    md += fmt::format("## Step {}: {}\n\n{}\n\n**Evidence.** {}.\n\n", k + 1, EffectName(s.effect),
                      diagnosis::EffectExplanation(s.effect), s.evidence.finding);
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

  const Discrepancy base = Discrepancy::Of(diagnosis::AssemblyOf(d.base, data), data);
  const Discrepancy final_fit = Discrepancy::Of(diagnosis::AssemblyOf(d.final_model, data), data);
  const auto base_rows = TestRows(base), final_rows = TestRows(final_fit);
  md += fmt::format(
      "## Loops, test by test\n\nMean over each test's half-cycles between reversals "
      "(amplitude: half the reversal-to-reversal range; period: twice the duration): energy "
      "dissipated per half-cycle [{f}*{l}] and secant stiffness between the reversals [{f}/{l}], "
      "measured and modelled.\n\n"
      "| test | amplitude [{l}] | period | W measured | W base | W final | K measured | K base | "
      "K final |\n|---|---|---|---|---|---|---|---|---|\n",
      fmt::arg("f", force), fmt::arg("l", length));
  for (std::size_t i = 0; i < base_rows.size(); ++i) {
    const auto& b = base_rows[i];
    const auto& f = final_rows[i];
    md += fmt::format(
        "| {} | {:.4g} | {:.3g} | {:.5g} | {:.5g} ({}) | {:.5g} ({}) | {:.4g} | {:.4g} ({}) | "
        "{:.4g} ({}) |\n",
        b.name, b.amplitude, b.period, b.energy_measured, b.energy_model,
        Deviation(b.energy_model, b.energy_measured), f.energy_model,
        Deviation(f.energy_model, f.energy_measured), b.secant_measured, b.secant_model,
        Deviation(b.secant_model, b.secant_measured), f.secant_model,
        Deviation(f.secant_model, f.secant_measured));
  }
  const auto base_bands = ResidualBands(base), final_bands = ResidualBands(final_fit);
  md +=
      "\n## Where the residual lies\n\nRMS residual in units of the estimated noise (1: the "
      "model misses by no more than noise), by |u| / u_a, on loading (u v > 0) and unloading "
      "branches.\n\n| model | branch | 0-25 % | 25-50 % | 50-75 % | 75-100 % |\n"
      "|---|---|---|---|---|---|\n";
  for (const auto& [name, bands] :
       {std::pair{"base", base_bands}, std::pair{"final", final_bands}}) {
    for (int branch = 0; branch < 2; ++branch) {
      md += fmt::format("| {} | {} |", name, branch == 0 ? "loading" : "unloading");
      for (int b = 0; b < kBands; ++b) md += fmt::format(" {:.2f} |", bands[branch * kBands + b]);
      md += "\n";
    }
  }
  md += fmt::format("\nSeed {}; {:.1f} s.\n", context.seed, d.seconds);
  return md;
}

}  // namespace isolab::cli
