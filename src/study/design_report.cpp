#include "isolab/study/design_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <variant>

#include "isolab/io/atomic_file.h"

namespace isolab::study {
namespace {

namespace fs = std::filesystem;

std::size_t Index(DesignQuantity q) { return static_cast<std::size_t>(q); }

std::string UnitOf(DesignQuantity q, const UnitSystem& units) {
  return QuantityUnit(SourceOf(q), units);
}

// "0.148 %", or why there is no value (a model without story heights has no drift ratio).
std::string Drift(double ratio) {
  return std::isnan(ratio) ? "n/a (no story has a height)" : fmt::format("{:.3g} %", ratio);
}

std::string DriftVerdict(double ratio, double limit) {
  if (std::isnan(ratio)) return "not checked";
  return ratio <= limit ? "met" : "EXCEEDED";
}

// The code's checks, once for the report and the terminal.
struct Checks {
  double elf_total = 0.0, rha_total = 0.0, design_total = 0.0;  // D_TM
  double elf_shear = 0.0, rha_shear = 0.0, design_shear = 0.0;  // V_b
  double drift = 0.0, drift_limit = 0.0;                        // ratios (%)
  std::string total_bound, shear_bound;
};

// `drift_limit`: the design's, a ratio.
Checks CheckDesign(const DesignOutcome& o, double drift_limit) {
  Checks c;
  for (const DesignBound& b : o.bounds) {
    c.elf_total = std::max(c.elf_total, b.elf_total_displacement);
    c.elf_shear = std::max(c.elf_shear, b.elf.base_shear);
  }
  const std::size_t t = o.governing[Index(DesignQuantity::kTotalDisplacement)];
  const std::size_t v = o.governing[Index(DesignQuantity::kBaseShear)];
  c.total_bound = o.bounds[t].bound;
  c.shear_bound = o.bounds[v].bound;
  c.rha_total = o.values[t][Index(DesignQuantity::kTotalDisplacement)].value;
  c.rha_shear = o.values[v][Index(DesignQuantity::kBaseShear)].value;
  c.design_total = std::max(c.rha_total, kElfDisplacementFloor * c.elf_total);
  c.design_shear = std::max(c.rha_shear, kElfShearFloor * c.elf_shear);
  const std::size_t d = o.governing[Index(DesignQuantity::kStoryDriftRatio)];
  c.drift = o.values[d][Index(DesignQuantity::kStoryDriftRatio)].value;
  c.drift_limit = 100.0 * drift_limit;
  return c;
}

// "upper: PGA 3.26 g exceeds 3 g (in 3 of 3 runs)", a line per bound and warning.
std::vector<std::string> WarningLines(const DesignOutcome& o) {
  const std::size_t per_bound = o.eccentricities.size() * o.records.size();
  std::vector<std::string> lines;
  for (const DesignWarning& w : o.warnings) {
    lines.push_back(fmt::format("{}: {} (in {} of its {} runs)", o.bounds[w.bound].bound, w.text,
                                w.runs, per_bound));
  }
  return lines;
}

// The first lines' note: the design values rest on runs that warned (of input no real building
// or record has, of a bearing at its restrainer, ...), so they are not to be used unread.
std::string WarningNote(const DesignOutcome& o) {
  return fmt::format(
      "WARNING: the runs gave {} warning{} (listed under \"Warnings\"): read {} before using "
      "the design values below.",
      o.warnings.size(), o.warnings.size() == 1 ? "" : "s", o.warnings.size() == 1 ? "it" : "them");
}

// "tfp_1, tfp_2, tfp_3, tfp_4" or "isolation".
std::string Names(const std::vector<std::string>& isolators) {
  return fmt::format("{}", fmt::join(isolators, ", "));
}

std::string CapacityRow(const CapacityCheck& c, const UnitSystem& u) {
  if (!c.capacity) {
    return fmt::format(
        "| D_TM <= displacement capacity of {} (ASCE 7-16 17.2.4) | {:.4g} {} | not known from "
        "the laws (a single pendulum or a lead-rubber bearing states none; an HDR bearing's needs "
        "shear_strain_limit) | not checked |",
        Names(c.isolators), c.demand, u.length());
  }
  return fmt::format(
      "| D_TM <= displacement capacity of {} (ASCE 7-16 17.2.4) | {:.4g} {} | "
      "{:.4g} {} ({}) | {} |",
      Names(c.isolators), c.demand, u.length(), c.capacity->displacement, u.length(),
      c.capacity->basis, c.met ? "met" : "EXCEEDED");
}

std::string StatisticText(const DesignOutcome& o) {
  return o.mean_of_suite ? fmt::format("mean of {} records", o.records.size())
                         : fmt::format("maximum of {} records (fewer than {}: no mean)",
                                       o.records.size(), kMinimumRecordsForMean);
}

void WriteValues(const model::DesignFile& design, const DesignOutcome& o, std::ostream& file) {
  const UnitSystem& u = design.model.units;
  const double second = 1.0 / u.SiFactor(dimension::kTime);
  fmt::print(file, "bound,quantity,unit,statistic,value\n");
  for (const DesignBound& b : o.bounds) {
    const auto row = [&](std::string_view q, const std::string& unit, double value) {
      fmt::print(file, "{},{},{},elf,{:.12g}\n", b.bound, q, unit, value);
    };
    row("D_M", u.length(), b.elf.displacement);
    row("T_M", "s", b.elf.period / second);
    row("beta_M", "1", b.elf.at_design.damping);
    row("B_M", "1", b.damping_coefficient);
    row("k_M", u.force() + "/" + u.length(), b.elf.at_design.stiffness);
    row("V_b", u.force(), b.elf.base_shear);
    row("D_TM", u.length(), b.elf_total_displacement);
  }
  fmt::print(file, "design,drift_limit,%,limit,{:.12g}\n", 100.0 * design.drift_limit);
  for (std::size_t b = 0; b < o.bounds.size(); ++b) {
    for (const DesignQuantityInfo& info : DesignQuantities()) {
      const DesignStatistic& s = o.values[b][Index(info.quantity)];
      const std::string unit = UnitOf(info.quantity, u);
      fmt::print(file, "{},{},{},mean,{:.12g}\n", o.bounds[b].bound, info.key, unit, s.mean);
      fmt::print(file, "{},{},{},max,{:.12g}\n", o.bounds[b].bound, info.key, unit, s.max);
    }
  }
}

// The `isolab run` that reproduces a run of the design, from the output folder: its case's model,
// its record (pair) and the record's factor. Empty where the command line cannot say it (a pair
// whose components carry different scales).
std::string RunCommand(const DesignOutcome& o, std::size_t b, std::size_t c, std::size_t r,
                       const fs::path& directory) {
  const fs::path folder = fs::absolute(directory).lexically_normal();
  const auto from_folder = [&](const std::string& path) {
    return fs::absolute(path).lexically_normal().lexically_relative(folder).string();
  };
  const model::StudyRecord& record = o.study.records[r];
  const std::vector<model::GroundMotionSection>& h = record.components;
  if (h.size() > 1 && h[1].scale != h[0].scale) return "";
  std::string command = "isolab run " + from_folder(o.bounds[b].case_model_files[c]) +
                        " --record " + from_folder(h[0].file);
  if (h.size() > 1) command += " --record-h2 " + from_folder(h[1].file);
  if (record.angle != 0.0) command += fmt::format(" --angle {:.17g}", record.angle);
  if (!h[0].units.empty()) command += " --units " + h[0].units;
  if (h[0].dt > 0.0) command += fmt::format(" --record-dt {:.17g}", h[0].dt);
  return command + fmt::format(" --scale {:.17g}", h[0].scale);
}

// A CSV field, quoted when it holds a comma or a quote.
std::string CsvField(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

void WriteRuns(const model::DesignFile& design, const DesignOutcome& o, const fs::path& directory,
               std::ostream& file) {
  fmt::print(file, "bound,eccentricity,record,factor,completed");
  for (const QuantityInfo& info : Quantities()) {
    fmt::print(file, ",{} [{}]", info.key, QuantityUnit(info.quantity, design.model.units));
  }
  fmt::print(file, ",file,command\n");
  const std::size_t C = o.eccentricities.size(), R = o.records.size();
  for (std::size_t b = 0; b < o.bounds.size(); ++b) {
    for (std::size_t c = 0; c < C; ++c) {
      for (std::size_t r = 0; r < R; ++r) {
        const JobResult& run = o.RunOf(b, c, r);
        fmt::print(file, "{},{},{},{:.12g},{}", o.bounds[b].bound, o.eccentricities[c].name,
                   o.records[r].name, o.records[r].factor, run.completed ? 1 : 0);
        for (const double v : run.values) fmt::print(file, ",{:.12g}", v);
        fmt::print(file, ",{},{}\n", run.file, CsvField(RunCommand(o, b, c, r, directory)));
      }
    }
  }
}

void WriteSpectra(const DesignOutcome& o, std::ostream& file) {
  fmt::print(file, "period_s,in_range,target_g");
  for (const DesignRecord& r : o.records) fmt::print(file, ",{}_g", r.name);
  fmt::print(file, ",mean_g\n");
  const double low = o.period_range[0] * (1 - 1e-12), high = o.period_range[1] * (1 + 1e-12);
  for (std::size_t p = 0; p < o.display_periods.size(); ++p) {
    const double t = o.display_periods[p];
    fmt::print(file, "{:.12g},{},{:.12g}", t, t >= low && t <= high ? 1 : 0, o.display_target[p]);
    double sum = 0.0;
    for (const DesignRecord& r : o.records) {
      fmt::print(file, ",{:.12g}", r.factor * r.spectrum[p]);
      sum += r.factor * r.spectrum[p];
    }
    fmt::print(file, ",{:.12g}\n", sum / static_cast<double>(o.records.size()));
  }
}

void WriteReport(const model::DesignFile& design, const DesignOutcome& o,
                 const std::string& directory, bool figures, std::ostream& md) {
  const UnitSystem& u = design.model.units;
  const double second = 1.0 / u.SiFactor(dimension::kTime);
  const auto relative = [&](const std::string& path) {
    return fs::path(path).lexically_relative(directory).string();
  };
  const Checks c = CheckDesign(o, design.drift_limit);
  fmt::print(md, "# Design of {}\n\n", design.model_path);
  if (!design.description.empty()) fmt::print(md, "{}\n\n", design.description);
  fmt::print(md, "Design file `{}`. Target: {}. Lengths in {}, forces in {}.\n\n", design.path,
             spectra::Describe(design.target), u.length(), u.force());
  if (!o.warnings.empty()) fmt::print(md, "**{}**\n\n", WarningNote(o));

  fmt::print(md, "## Bound models\n\n");
  fmt::print(md,
             "The bearings' properties at nominal, upper-bound and lower-bound values (ASCE "
             "7-16 17.2.8.4), each a model that runs alone:\n\n");
  for (const DesignBound& b : o.bounds) {
    fmt::print(md, "- {}: `{}`\n", b.bound, relative(b.model_file));
  }

  fmt::print(md, "\n## Equivalent lateral force procedure (ASCE 7-16 17.5)\n\n");
  fmt::print(md,
             "| bound | D_M ({0}) | T_M (s) | beta_M | B_M | k_M ({1}/{0}) | V_b ({1}) | "
             "D_TM ({0}) |\n|---|---|---|---|---|---|---|---|\n",
             u.length(), u.force());
  for (const DesignBound& b : o.bounds) {
    fmt::print(md, "| {} | {:.4g} | {:.4g} | {:.3g} | {:.3g} | {:.4g} | {:.4g} | {:.4g} |\n",
               b.bound, b.elf.displacement, b.elf.period / second, b.elf.at_design.damping,
               b.damping_coefficient, b.elf.at_design.stiffness, b.elf.base_shear,
               b.elf_total_displacement);
  }
  fmt::print(md,
             "\n{} at the bearings' effective stiffness and damping at D_M, from their own "
             "laws (three cycles at D_M, the third read).\n",
             std::holds_alternative<spectra::Asce7Spectrum>(design.target)
                 ? "D_M = g S_M1 T_M / (4 pi^2 B_M) (Eq. 17.5-1), B_M from Table 17.5-1,"
             : std::holds_alternative<spectra::Eurocode8Spectrum>(design.target)
                 ? "D_M = Sa(T_M) g T_M^2 / (4 pi^2 B_M), the target's spectral displacement, "
                   "B_M = 1 / eta (EN 1998-1 Eq. 3.6),"
                 : "D_M = Sa(T_M) g T_M^2 / (4 pi^2 B_M), the target's spectral displacement, "
                   "B_M from ASCE 7-16 Table 17.5-1,");

  if (const std::string rule = BearingWeightRule(design.model, o); !rule.empty()) {
    fmt::print(md, "\n### Bearing weights\n\n");
    fmt::print(md, "The friction pendulums' forces are their weight times constants: {}.\n\n",
               rule.substr(rule.find(": ") + 2));
    fmt::print(md, "| bearing | laws' w ({0}) | carried ({0}) |\n|---|---|---|\n", u.force());
    for (const analysis::IsolationSystem::BearingWeight& w : o.bearing_weights) {
      if (!std::isnan(w.carried)) {
        fmt::print(md, "| {} | {:.5g} | {:.5g} |\n", w.name, w.law, w.carried);
      }
    }
  }

  fmt::print(md, "\n## The suite\n\n");
  fmt::print(md,
             "{} {}, each scaled by its own factor so that the mean of their {} is nowhere "
             "below the target from {:.3g} s ({:g} T_M upper) to {:.3g} s ({:g} T_M lower). "
             "Common factor {:.4g}; the mean touches the target at {:.3g} s.\n\n",
             o.records.size(), o.study.directions == 2 ? "pairs" : "records",
             o.study.directions == 2 ? "RotD100 spectra" : "5 % spectra", o.period_range[0],
             design.period_range[0], o.period_range[1], design.period_range[1],
             o.scaling.common_factor, o.scaling.periods[o.scaling.governing]);
  fmt::print(md, "| record | shape factor | factor | matched to |\n|---|---|---|---|\n");
  const std::string matched_note =
      o.study.directions == 2 ? "" : " (the pair's RotD100; its H1 runs)";
  for (const DesignRecord& r : o.records) {
    fmt::print(md, "| {} | {:.4g} | {:.4g} | {} |\n", r.name, r.shape_factor, r.factor,
               r.misfit >= 0 ? fmt::format("{:.3g}{}", r.misfit, matched_note) : "(given)");
  }
  if (figures) {
    fmt::print(md, "\n![The scaled suite's spectra against the target](design_spectra.png)\n");
  }

  fmt::print(md, "\n## Response-history design values\n\n");
  fmt::print(md,
             "{} bounds x {} eccentricity cases ({}) x {} records = {} runs. Per bound and "
             "record the envelope over the eccentricity cases (D_M: without eccentricity), "
             "then the {}.\n\n",
             o.bounds.size(), o.eccentricities.size(),
             fmt::join(
                 [&] {
                   std::vector<std::string> names;
                   for (const auto& e : o.eccentricities) names.push_back(e.name);
                   return names;
                 }(),
                 ", "),
             o.records.size(), o.runs.size(), StatisticText(o));
  fmt::print(md, "| quantity |");
  for (const DesignBound& b : o.bounds) fmt::print(md, " {} |", b.bound);
  fmt::print(md, " governing |\n|---|");
  for (std::size_t b = 0; b <= o.bounds.size(); ++b) fmt::print(md, "---|");
  fmt::print(md, "\n");
  for (const DesignQuantityInfo& info : DesignQuantities()) {
    fmt::print(md, "| {} ({}) |", info.label, UnitOf(info.quantity, u));
    for (std::size_t b = 0; b < o.bounds.size(); ++b) {
      fmt::print(md, " {:.4g} |", o.values[b][Index(info.quantity)].value);
    }
    fmt::print(md, " {} |\n", o.bounds[o.governing[Index(info.quantity)]].bound);
  }

  fmt::print(md, "\n## Warnings\n\n");
  if (o.warnings.empty()) fmt::print(md, "None: no run warned of implausible input.\n");
  for (const std::string& line : WarningLines(o)) fmt::print(md, "- {}\n", line);

  fmt::print(md, "\n## Checks\n\n");
  fmt::print(md, "| check | response history | limit | design value |\n|---|---|---|---|\n");
  fmt::print(md,
             "| D_TM >= {:g} D_TM (ELF) (ASCE 7-16 17.6.3) | {:.4g} {} ({}) | {:.4g} {} | "
             "{:.4g} {} |\n",
             kElfDisplacementFloor, c.rha_total, u.length(), c.total_bound,
             kElfDisplacementFloor * c.elf_total, u.length(), c.design_total, u.length());
  fmt::print(md,
             "| V_b >= {:g} V_b (ELF) (ASCE 7-16 17.6.3) | {:.4g} {} ({}) | {:.4g} {} | "
             "{:.4g} {} |\n",
             kElfShearFloor, c.rha_shear, u.force(), c.shear_bound, kElfShearFloor * c.elf_shear,
             u.force(), c.design_shear, u.force());
  fmt::print(md, "| story drift ratio <= {:g} % | {} | {:g} % | {} |\n", c.drift_limit,
             Drift(c.drift), c.drift_limit, DriftVerdict(c.drift, c.drift_limit));
  fmt::print(md,
             "\n| capacity check | D_TM (design value) | capacity | verdict |\n"
             "|---|---|---|---|\n");
  for (const CapacityCheck& check : CheckCapacities(o)) {
    fmt::print(md, "{}\n", CapacityRow(check, u));
  }

  fmt::print(md, "\n## Figures\n\n");
  if (!figures) {
    fmt::print(md, "Not drawn here: `scripts/plot_design.py {}` draws them from this folder.\n",
               directory);
    return;
  }
  fmt::print(md,
             "Histories kept for record {} (the largest D_TM of the governing bound), each "
             "bound in its worst eccentricity case: `{}`.\n\n",
             o.records[o.figure_record].name, fmt::join(o.history_files, "`, `"));
  fmt::print(md, "![The worst bearing's loops at the three bounds](design_loops.png)\n\n");
  if (o.study.directions == 2) {
    fmt::print(md, "![The orbits of the bearings that move most](design_orbits.png)\n\n");
  }
  if (!std::isnan(c.drift)) fmt::print(md, "![Peak story drift ratios](design_drifts.png)\n");
}

}  // namespace

std::vector<CapacityCheck> CheckCapacities(const DesignOutcome& o) {
  const double demand = CheckDesign(o, 0.0).design_total;
  std::vector<CapacityCheck> checks;
  for (const IsolatorCapacity& c : o.capacities) {
    const auto same = std::find_if(checks.begin(), checks.end(), [&](const CapacityCheck& k) {
      return k.capacity.has_value() == c.capacity.has_value() &&
             (!c.capacity || (k.capacity->displacement == c.capacity->displacement &&
                              k.capacity->basis == c.capacity->basis));
    });
    if (same != checks.end()) {
      same->isolators.push_back(c.isolator);
      continue;
    }
    checks.push_back(
        {{c.isolator}, c.capacity, demand, c.capacity && demand <= c.capacity->displacement});
  }
  return checks;
}

void WriteDesignFiles(const model::DesignFile& design, const DesignOutcome& outcome,
                      const std::string& output_directory, bool figures) {
  const fs::path dir(output_directory);
  io::WriteTextFileAtomically((dir / "design_values.csv").string(),
                              [&](std::ostream& f) { WriteValues(design, outcome, f); });
  io::WriteTextFileAtomically((dir / "design_runs.csv").string(),
                              [&](std::ostream& f) { WriteRuns(design, outcome, dir, f); });
  io::WriteTextFileAtomically((dir / "design_spectra.csv").string(),
                              [&](std::ostream& f) { WriteSpectra(outcome, f); });
  io::WriteTextFileAtomically((dir / "design.md").string(), [&](std::ostream& f) {
    WriteReport(design, outcome, output_directory, figures, f);
  });
}

std::string DesignSummaryText(const model::DesignFile& design, const DesignOutcome& o) {
  const UnitSystem& u = design.model.units;
  const Checks c = CheckDesign(o, design.drift_limit);
  std::ostringstream out;
  if (!o.warnings.empty()) fmt::print(out, "{}\n", WarningNote(o));
  fmt::print(out, "design values ({}):\n", StatisticText(o));
  fmt::print(out, "{:<54}", "");
  for (const DesignBound& b : o.bounds) fmt::print(out, " {:>12}", b.bound);
  fmt::print(out, "  governing\n");
  for (const DesignQuantityInfo& info : DesignQuantities()) {
    fmt::print(out, "{:<54}", fmt::format("{} ({})", info.label, UnitOf(info.quantity, u)));
    for (std::size_t b = 0; b < o.bounds.size(); ++b) {
      fmt::print(out, " {:>12.5g}", o.values[b][Index(info.quantity)].value);
    }
    fmt::print(out, "  {}\n", o.bounds[o.governing[Index(info.quantity)]].bound);
  }
  fmt::print(out, "D_TM {:.5g} {} ({}), ELF floor {:g} x {:.5g} = {:.5g}: design D_TM {:.5g} {}\n",
             c.rha_total, u.length(), c.total_bound, kElfDisplacementFloor, c.elf_total,
             kElfDisplacementFloor * c.elf_total, c.design_total, u.length());
  fmt::print(out, "V_b {:.5g} {} ({}), ELF floor {:g} x {:.5g} = {:.5g}: design V_b {:.5g} {}\n",
             c.rha_shear, u.force(), c.shear_bound, kElfShearFloor, c.elf_shear,
             kElfShearFloor * c.elf_shear, c.design_shear, u.force());
  fmt::print(out, "story drift ratio {} against {:g} %: {}\n", Drift(c.drift), c.drift_limit,
             DriftVerdict(c.drift, c.drift_limit));
  for (const CapacityCheck& check : CheckCapacities(o)) {
    if (check.capacity) {
      fmt::print(out,
                 "D_TM {:.5g} {} against the displacement capacity of {}, {:.5g} {} ({}): {}\n",
                 check.demand, u.length(), Names(check.isolators), check.capacity->displacement,
                 u.length(), check.capacity->basis, check.met ? "met" : "EXCEEDED");
    } else {
      fmt::print(out, "displacement capacity of {}: not known from the laws, not checked\n",
                 Names(check.isolators));
    }
  }
  if (!o.warnings.empty()) fmt::print(out, "warnings:\n");
  for (const std::string& line : WarningLines(o)) fmt::print(out, "  {}\n", line);
  return out.str();
}

}  // namespace isolab::study
