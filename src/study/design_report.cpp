#include "isolab/study/design_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <sstream>
#include <variant>

#include "isolab/io/atomic_file.h"
#include "isolab/io/csv.h"

namespace isolab::study {
namespace {

namespace fs = std::filesystem;

std::string UnitOf(DesignQuantity q, const UnitSystem& units) {
  return QuantityUnit(SourceOf(q), units);
}

// "upper: PGA 3.26 g exceeds 3 g (in 3 of 3 runs)", a line per bound and warning.
std::vector<std::string> WarningLines(const DesignOutcome& o) {
  const std::size_t per_bound = o.RunsPerBound();
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

// How the suite was scaled, by the code's rule, with the numbers.
std::string SuiteRuleText(const model::DesignFile& design, const DesignOutcome& o) {
  const bool pairs = o.study.directions == 2;
  const std::string head = fmt::format(
      "{} {}, each scaled by its own factor so that the mean of their {} is nowhere below {} from "
      "{:.3g} s ({:g} T_M upper) to {:.3g} s ({:g} T_M lower{})",
      o.records.size(), pairs ? "pairs" : "records",
      !pairs                                        ? "5 % spectra"
      : design.code == model::DesignCode::kEn1998_1 ? "components' 5 % spectra"
                                                    : "RotD100 spectra",
      o.target_fraction == 1.0 ? std::string("the target")
                               : fmt::format("{:g} % of the target", 100.0 * o.target_fraction),
      o.period_range[0], design.period_range[0], o.period_range[1], design.period_range[1],
      o.uncut_range_top > 0.0
          ? fmt::format(", cut from {:.3g} s at 4 s, where EN 1998-1 3.2.2.2's spectrum ends",
                        o.uncut_range_top)
          : "");
  if (design.code != model::DesignCode::kEn1998_1) {
    return head + fmt::format(
                      " (ASCE 7-16 17.3.3). Common factor {:.4g}; the mean touches the target at "
                      "{:.3g} s.",
                      o.scaling.common_factor, o.scaling.periods[o.scaling.governing]);
  }
  return head +
         fmt::format(
             " (EN 1998-1 3.2.3.1.2(4)c with T_1 the isolated period T_M; a narrower range "
             "section 10 may set for isolated buildings is not at hand here and is not applied), "
             "and their mean peak ground acceleration{}, {:.4g} g, is not below a_g S = {:.4g} g "
             "(3.2.3.1.2(4)b). Common factor {:.4g}; {}.",
             pairs ? " (of the components, each a time history)" : "", o.mean_pga, o.pga_floor,
             o.scaling.common_factor,
             o.pga_governs
                 ? std::string("the mean peak ground acceleration sets it")
                 : fmt::format("the mean touches {:g} % of the target at {:.3g} s",
                               100.0 * o.target_fraction, o.scaling.periods[o.scaling.governing]));
}

// "12.3 mm", or "-" for a value the check has none of.
std::string Amount(double value, const std::string& unit) {
  return std::isnan(value) ? "-" : fmt::format("{:.4g} {}", value, unit);
}

// "D_TM 524.6 mm (upper: 480.1 mm, not below 0.8 D_TM (ELF), ASCE 7-16 17.6.3)"
std::string DesignValueText(std::string_view name, const DesignValue& v, const DesignOutcome& o,
                            const std::string& unit) {
  std::string text = fmt::format("design {} {:.5g} {}: {} bound's {:.5g} {}", name, v.value, unit,
                                 o.bounds[v.bound].bound, v.response_history, unit);
  if (v.factor != 1.0) text += fmt::format(" x {:g}", v.factor);
  if (v.floor > 0.0) {
    text +=
        fmt::format(", ELF floor {:g} x {:.5g} = {:.5g} {}", v.floor, v.elf, v.floor * v.elf, unit);
  }
  return text + fmt::format(" ({})", v.rule);
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
  fmt::print(file, "design,target_fraction,1,rule,{:.12g}\n", o.target_fraction);
  fmt::print(file, "design,directions,1,model,{}\n", o.study.directions);
  fmt::print(file, "design,pga_governs,1,rule,{}\n", o.pga_governs ? 1 : 0);
  fmt::print(file, "design,mean_of_suite,1,rule,{}\n", o.mean_of_suite ? 1 : 0);
  fmt::print(file, "design,D_TM,{},design,{:.12g}\n", u.length(),
             o.checks.total_displacement.value);
  fmt::print(file, "design,V_b,{},design,{:.12g}\n", u.force(), o.checks.base_shear.value);
  if (const auto& s = o.checks.superstructure) {
    for (std::size_t b = 0; b < o.bounds.size(); ++b) {
      fmt::print(file, "{},V_st,{},elf,{:.12g}\n", o.bounds[b].bound, u.force(), s->v_st[b]);
    }
    fmt::print(file, "design,V_s,{},elf,{:.12g}\n", u.force(), s->elf);
    fmt::print(file, "design,V_s,{},design,{:.12g}\n", u.force(), s->v_s.value);
  }
  for (std::size_t b = 0; b < o.bounds.size(); ++b) {
    for (const DesignQuantityInfo& info : DesignQuantities()) {
      const DesignStatistic& s = o.values[b][IndexOf(info.quantity)];
      const std::string unit = UnitOf(info.quantity, u);
      fmt::print(file, "{},{},{},mean,{:.12g}\n", o.bounds[b].bound, info.key, unit, s.mean);
      fmt::print(file, "{},{},{},max,{:.12g}\n", o.bounds[b].bound, info.key, unit, s.max);
    }
  }
}

// The `isolab run` that reproduces a run of the design, from the output folder: its case's model,
// its record (pair) at its angle (`s`: the index in the study's records) and the record's factor.
// Empty where the command line cannot say it (a pair whose components carry different scales).
std::string RunCommand(const DesignOutcome& o, std::size_t b, std::size_t c, std::size_t s,
                       const fs::path& directory) {
  const fs::path folder = fs::absolute(directory).lexically_normal();
  const auto from_folder = [&](const std::string& path) {
    return fs::absolute(path).lexically_normal().lexically_relative(folder).string();
  };
  const model::StudyRecord& record = o.study.records[s];
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

void WriteRuns(const model::DesignFile& design, const DesignOutcome& o, const fs::path& directory,
               std::ostream& file) {
  fmt::print(file, "bound,eccentricity,record,orientation,factor,completed");
  for (const QuantityInfo& info : Quantities()) {
    fmt::print(file, ",{} [{}]", info.key, QuantityUnit(info.quantity, design.model.units));
  }
  fmt::print(file, ",file,command\n");
  const std::size_t C = o.eccentricities.size(), R = o.records.size();
  const std::size_t O = o.orientations.size();
  for (std::size_t b = 0; b < o.bounds.size(); ++b) {
    for (std::size_t c = 0; c < C; ++c) {
      for (std::size_t r = 0; r < R; ++r) {
        for (std::size_t k = 0; k < O; ++k) {
          const JobResult& run = o.RunOf(b, c, r, k);
          fmt::print(file, "{},{},{},{:g},{:.12g},{}", o.bounds[b].bound, o.eccentricities[c].name,
                     io::CsvField(o.records[r].name), o.orientations[k], o.records[r].factor,
                     run.completed ? 1 : 0);
          for (const double v : run.values) fmt::print(file, ",{:.12g}", v);
          fmt::print(file, ",{},{}\n", run.file,
                     io::CsvField(RunCommand(o, b, c, r * O + k, directory)));
        }
      }
    }
  }
}

void WriteChecks(const DesignOutcome& o, std::ostream& file) {
  fmt::print(file, "check,clause,unit,demand,limit,basis,verdict\n");
  for (const DesignCheck& c : o.checks.checks) {
    fmt::print(file, "{},{},{},{:.12g},{:.12g},{},{}\n", io::CsvField(c.check),
               io::CsvField(c.clause), c.unit, c.demand, c.limit, io::CsvField(c.basis),
               VerdictName(c.verdict));
  }
}

void WriteParts(const model::DesignFile& design, const DesignOutcome& o, std::ostream& file) {
  fmt::print(file, "bound,quantity,part,unit,statistic,value\n");
  for (const DesignPartValue& p : o.parts) {
    const std::string unit = PartQuantityUnit(p.quantity, design.model.units);
    const char* extreme = p.quantity == PartQuantity::kLeastAxialLoad ? "min" : "max";
    for (std::size_t b = 0; b < o.bounds.size(); ++b) {
      fmt::print(file, "{},{},{},{},mean,{:.12g}\n", o.bounds[b].bound,
                 PartQuantityName(p.quantity), io::CsvField(p.part), unit, p.bounds[b].mean);
      fmt::print(file, "{},{},{},{},{},{:.12g}\n", o.bounds[b].bound, PartQuantityName(p.quantity),
                 io::CsvField(p.part), unit, extreme, p.bounds[b].max);
    }
  }
}

// A table of parts (rows: the parts in the runs' order) and their quantities (columns), each cell
// the governing design value and its bound.
void WritePartTable(const DesignOutcome& o, const UnitSystem& u, std::string_view heading,
                    std::initializer_list<std::pair<PartQuantity, std::string_view>> wanted,
                    std::ostream& md) {
  // The columns some part has a value of (a model without axial loads has none of theirs).
  std::vector<std::pair<PartQuantity, std::string_view>> columns;
  std::vector<std::string> rows;
  for (const auto& [q, label] : wanted) {
    bool any = false;
    for (const DesignPartValue& p : o.parts) {
      if (p.quantity != q || std::isnan(p.bounds[p.governing].value)) continue;
      any = true;
      if (std::find(rows.begin(), rows.end(), p.part) == rows.end()) rows.push_back(p.part);
    }
    if (any) columns.emplace_back(q, label);
  }
  if (rows.empty()) return;
  fmt::print(md, "| {} |", heading);
  for (const auto& [q, label] : columns)
    fmt::print(md, " {} ({}) |", label, PartQuantityUnit(q, u));
  fmt::print(md, "\n|---|");
  for (std::size_t k = 0; k < columns.size(); ++k) fmt::print(md, "---|");
  fmt::print(md, "\n");
  for (const std::string& row : rows) {
    fmt::print(md, "| {} |", row);
    for (const auto& [q, label] : columns) {
      const auto part = std::find_if(o.parts.begin(), o.parts.end(), [&](const DesignPartValue& p) {
        return p.quantity == q && p.part == row;
      });
      if (part == o.parts.end() || std::isnan(part->bounds[part->governing].value)) {
        fmt::print(md, " - |");
      } else {
        fmt::print(md, " {:.4g} ({}) |", part->bounds[part->governing].value,
                   o.bounds[part->governing].bound);
      }
    }
    fmt::print(md, "\n");
  }
  fmt::print(md, "\n");
}

// Each isolator's properties at its bound's D_M, and the bilinear loop of the same area and
// secant (its yield displacement neglected): Qd = E / (4 D), Kd = k_eff - Qd / D.
void WriteBearings(const model::DesignFile& design, const DesignOutcome& o, std::ostream& file) {
  const UnitSystem& u = design.model.units;
  fmt::print(file,
             "bound,bearing,D_M [{0}],k_eff [{1}/{0}],beta_eff,energy_per_cycle [{1}*{0}],"
             "Qd_equivalent [{1}],Kd_equivalent [{1}/{0}]\n",
             u.length(), u.force());
  for (const DesignBound& b : o.bounds) {
    for (std::size_t i = 0; i < b.bearings.size(); ++i) {
      const design::EffectiveProperties& p = b.bearings[i];
      const double qd = p.dissipated / (4.0 * p.displacement);
      fmt::print(file, "{},{},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g},{:.12g}\n", b.bound,
                 io::CsvField(o.bearing_weights[i].name), p.displacement, p.stiffness, p.damping,
                 p.dissipated, qd, p.stiffness - qd / p.displacement);
    }
  }
}

// The isolators' effective properties at each bound's D_M, one row per group of isolators whose
// properties are the same at every bound.
void WriteBearingTable(const DesignOutcome& o, const UnitSystem& u, std::ostream& md) {
  std::vector<std::vector<std::size_t>> groups;
  const auto same = [&](std::size_t i, std::size_t j) {
    for (const DesignBound& b : o.bounds) {
      const design::EffectiveProperties &p = b.bearings[i], &q = b.bearings[j];
      if (std::abs(p.stiffness - q.stiffness) > 1e-9 * std::abs(p.stiffness) ||
          std::abs(p.damping - q.damping) > 1e-9) {
        return false;
      }
    }
    return true;
  };
  for (std::size_t i = 0; i < o.bearing_weights.size(); ++i) {
    const auto group = std::find_if(groups.begin(), groups.end(),
                                    [&](const auto& g) { return same(g.front(), i); });
    if (group != groups.end()) {
      group->push_back(i);
    } else {
      groups.push_back({i});
    }
  }
  fmt::print(md,
             "\nEach bearing at its bound's D_M, from its own law (`design_bearings.csv` adds the "
             "energy per cycle and the bilinear loop of the same area and secant, Qd and Kd, for "
             "another program's link properties):\n\n| bearings |");
  for (const DesignBound& b : o.bounds)
    fmt::print(md, " k_eff {} ({}/{}) |", b.bound, u.force(), u.length());
  for (const DesignBound& b : o.bounds) fmt::print(md, " beta_eff {} |", b.bound);
  fmt::print(md, "\n|---|");
  for (std::size_t k = 0; k < 2 * o.bounds.size(); ++k) fmt::print(md, "---|");
  fmt::print(md, "\n");
  for (const std::vector<std::size_t>& g : groups) {
    std::vector<std::string> names;
    for (const std::size_t i : g) names.push_back(o.bearing_weights[i].name);
    fmt::print(md, "| {} |", fmt::join(names, ", "));
    for (const DesignBound& b : o.bounds)
      fmt::print(md, " {:.4g} |", b.bearings[g.front()].stiffness);
    for (const DesignBound& b : o.bounds)
      fmt::print(md, " {:.3g} |", b.bearings[g.front()].damping);
    fmt::print(md, "\n");
  }
}

void WriteSpectra(const DesignOutcome& o, std::ostream& file) {
  fmt::print(file, "period_s,in_range,target_g");
  for (const DesignRecord& r : o.records) fmt::print(file, ",{}", io::CsvField(r.name + "_g"));
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

// The first screen: the design values, how the checks came out, and what the analysis leaves
// out.
void WriteSummary(const model::DesignFile& design, const DesignOutcome& o, std::ostream& md) {
  const UnitSystem& u = design.model.units;
  const DesignChecks& c = o.checks;
  fmt::print(md, "## Summary\n\n");
  fmt::print(md, "- Design D_TM {:.4g} {} ({} bound; {}).\n", c.total_displacement.value,
             u.length(), o.bounds[c.total_displacement.bound].bound, c.total_displacement.rule);
  fmt::print(md, "- Design V_b {:.4g} {} ({} bound; {}).\n", c.base_shear.value, u.force(),
             o.bounds[c.base_shear.bound].bound, c.base_shear.rule);
  if (c.superstructure) {
    fmt::print(md, "- Design V_s {:.4g} {} (R_I {:g}).\n", c.superstructure->v_s.value, u.force(),
               c.superstructure->r_i);
  }
  std::size_t met = 0, exceeded = 0, unchecked = 0;
  std::vector<std::string> failed;
  for (const DesignCheck& check : c.checks) {
    if (check.verdict == Verdict::kMet) ++met;
    if (check.verdict == Verdict::kNotChecked) ++unchecked;
    if (check.verdict == Verdict::kExceeded) {
      ++exceeded;
      failed.push_back(check.check);
    }
  }
  fmt::print(md, "- Checks: {} met, {}, {} not checked (\"Checks\" below).\n", met,
             failed.empty() ? std::string("none exceeded")
                            : fmt::format("{} EXCEEDED ({})", exceeded, fmt::join(failed, "; ")),
             unchecked);
  fmt::print(md, "- {} run warning{} (\"Warnings\" below).\n", o.warnings.size(),
             o.warnings.size() == 1 ? "" : "s");
  const bool overturning = design.model.axial_load && design.model.axial_load->overturning;
  fmt::print(md,
             "- What the analysis does not model: the building is a shear building of rigid "
             "floors (its stories' members are not modelled, so there are no member forces), "
             "without P-Delta effects and without a vertical component of the ground motion{}."
             "\n\n",
             design.model.axial_load && !overturning
                 ? "; the bearings' axial loads are their static shares, without overturning"
                 : "");
}

// The bound models' files and the modified properties with their lambdas.
void WriteBoundModels(const model::DesignFile& design, const DesignOutcome& o,
                      const std::string& directory, std::ostream& md) {
  const bool eurocode = design.code == model::DesignCode::kEn1998_1;
  const auto relative = [&](const std::string& path) {
    return fs::path(path).lexically_relative(directory).string();
  };
  fmt::print(md, "## Bound models\n\n");
  fmt::print(md,
             "The bearings' properties at nominal, upper-bound and lower-bound values ({}), "
             "each a model that runs alone:\n\n",
             eurocode ? "the design file's modification factors"
                      : "ASCE 7-16 17.2.8.4, the factors combined as 17.2.8.4 combines them");
  for (const DesignBound& b : o.bounds) {
    fmt::print(md, "- {}: `{}`", b.bound, relative(b.model_file));
    if (!b.opensees_file.empty()) {
      fmt::print(md, "; its bearings as OpenSees elements: `{}`", relative(b.opensees_file));
    }
    fmt::print(md, "\n");
  }
  if (!o.opensees_refused.empty()) {
    fmt::print(md, "\nThe bearings are not exported to OpenSees: {}\n", o.opensees_refused);
  } else {
    fmt::print(md,
               "\nThe OpenSees files define each bearing (`isolab_bearing NAME iNode jNode`) with "
               "the elements docs/bearings.md maps its law to; `design_bearings.csv` gives the "
               "linear properties another program's link takes.\n");
  }
  fmt::print(md,
             "\n| bearing | component | property | lambda_min | lambda_max | lower | nominal | "
             "upper |\n|---|---|---|---|---|---|---|---|\n");
  for (const model::BoundProperty& p : o.modified) {
    fmt::print(md, "| {} | {} | {} | {:.4g} | {:.4g} | {} | {} | {} |\n", p.bearing, p.component,
               p.key, p.lambda.min, p.lambda.max, p.lower, p.nominal, p.upper);
  }
}

// The code's simplified procedure per bound (ASCE 7-16 17.5, EN 1998-1 10.9.3).
void WriteElfSection(const model::DesignFile& design, const DesignOutcome& o, std::ostream& md) {
  const UnitSystem& u = design.model.units;
  const double second = 1.0 / u.SiFactor(dimension::kTime);
  const bool eurocode = design.code == model::DesignCode::kEn1998_1;
  fmt::print(md, "\n## {}\n\n",
             eurocode ? "Simplified linear analysis (EN 1998-1 10.9.3)"
                      : "Equivalent lateral force procedure (ASCE 7-16 17.5)");
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
  if (eurocode) {
    fmt::print(md,
               "D_TM amplifies D_M for torsion by ASCE 7-16 Eq. 17.5-3 (not below 1.15 D_M): EN "
               "1998-1 10.9.3's own amplification is not at hand here and is not applied. V_b = "
               "k_M D_M.\n");
  }
}

// The weights the friction pendulums carry, where the model has any.
void WriteBearingWeights(const model::DesignFile& design, const DesignOutcome& o,
                         std::ostream& md) {
  const UnitSystem& u = design.model.units;
  if (const std::string rule = BearingWeightRule(design.model, o); !rule.empty()) {
    fmt::print(md, "\n### Bearing weights\n\n");
    fmt::print(md, "The friction pendulums' forces are their weight times constants: {}.\n\n",
               rule.substr(rule.find(": ") + 2));
    fmt::print(md, "| bearing | laws' w ({0}) | carried ({0}) |\n|---|---|---|\n", u.force());
    for (const design::IsolationSystem::BearingWeight& w : o.bearing_weights) {
      if (!std::isnan(w.carried)) {
        fmt::print(md, "| {} | {:.5g} | {:.5g} |\n", w.name, w.law, w.carried);
      }
    }
  }
}

// The suite's rule, records and factors.
void WriteSuiteSection(const model::DesignFile& design, const DesignOutcome& o, bool figures,
                       std::ostream& md) {
  fmt::print(md, "\n## The suite\n\n");
  fmt::print(md, "{}\n\n", SuiteRuleText(design, o));
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
}

// The headline values per bound, then each story's, floor's and bearing's.
void WriteResponseHistoryValues(const model::DesignFile& design, const DesignOutcome& o,
                                std::ostream& md) {
  const UnitSystem& u = design.model.units;
  fmt::print(md, "\n## Response-history design values\n\n");
  std::vector<std::string> cases;
  for (const auto& e : o.eccentricities) cases.push_back(e.name);
  const bool turned = o.orientations.size() > 1;
  fmt::print(md,
             "{} bounds x {} eccentricity cases ({}) x {} records{} = {} runs. Per bound and "
             "record the envelope over the eccentricity cases (D_M: without eccentricity){}, "
             "then the {}.\n\n",
             o.bounds.size(), o.eccentricities.size(), fmt::join(cases, ", "), o.records.size(),
             turned ? fmt::format(" x {} orientations ({} degrees from x to H1)",
                                  o.orientations.size(), fmt::join(o.orientations, ", "))
                    : "",
             o.runs.size(), turned ? " and the orientations" : "", StatisticText(o));
  fmt::print(md, "| quantity |");
  for (const DesignBound& b : o.bounds) fmt::print(md, " {} |", b.bound);
  fmt::print(md, " governing |\n|---|");
  for (std::size_t b = 0; b <= o.bounds.size(); ++b) fmt::print(md, "---|");
  fmt::print(md, "\n");
  for (const DesignQuantityInfo& info : DesignQuantities()) {
    fmt::print(md, "| {} ({}) |", info.label, UnitOf(info.quantity, u));
    for (std::size_t b = 0; b < o.bounds.size(); ++b) {
      fmt::print(md, " {:.4g} |", o.values[b][IndexOf(info.quantity)].value);
    }
    fmt::print(md, " {} |\n", o.bounds[o.governing[IndexOf(info.quantity)]].bound);
  }

  fmt::print(md,
             "\n## Stories, floors and bearings\n\n"
             "Each part's design value from the response history, as above (per bound and record "
             "the envelope over the cases{}, then the {}), with the bound that governs it: the "
             "largest, or for a least axial load the least. Every bound's values are in "
             "`design_parts.csv`.\n\n",
             o.orientations.size() > 1 ? " and orientations" : "", StatisticText(o));
  WritePartTable(
      o, u, "story",
      {{PartQuantity::kStoryDriftRatio, "drift ratio"}, {PartQuantity::kStoryShear, "shear"}}, md);
  WritePartTable(o, u, "floor", {{PartQuantity::kFloorAcceleration, "absolute acceleration"}}, md);
  WritePartTable(o, u, "bearing",
                 {{PartQuantity::kIsolatorDisplacement, "displacement"},
                  {PartQuantity::kGreatestAxialLoad, "greatest axial load"},
                  {PartQuantity::kLeastAxialLoad, "least axial load"}},
                 md);
}

void WriteWarningsSection(const DesignOutcome& o, std::ostream& md) {
  fmt::print(md, "\n## Warnings\n\n");
  if (o.warnings.empty()) fmt::print(md, "None: no run warned of implausible input.\n");
  for (const std::string& line : WarningLines(o)) fmt::print(md, "- {}\n", line);
}

// The code's design values (D_TM, V_b, V_s) with their floors or factors.
void WriteDesignValues(const model::DesignFile& design, const DesignOutcome& o, std::ostream& md) {
  const UnitSystem& u = design.model.units;
  const DesignChecks& c = o.checks;
  fmt::print(md, "\n## Design values ({})\n\n", model::CodeName(design.code));
  fmt::print(md,
             "| value | governing bound | response history | factor | ELF floor | design value "
             "| rule |\n|---|---|---|---|---|---|---|\n");
  const auto value_row = [&](std::string_view name, const DesignValue& v, const std::string& unit) {
    fmt::print(md, "| {} | {} | {:.4g} {} | {:g} | {} | {:.4g} {} | {} |\n", name,
               o.bounds[v.bound].bound, v.response_history, unit, v.factor,
               v.floor > 0.0 ? fmt::format("{:g} x {:.4g} {}", v.floor, v.elf, unit) : "none",
               v.value, unit, v.rule);
  };
  value_row("D_TM", c.total_displacement, u.length());
  value_row("V_b", c.base_shear, u.force());
  if (c.superstructure) value_row("V_s", c.superstructure->v_s, u.force());
  if (const auto& s = c.superstructure) {
    fmt::print(md,
               "\nV_s (ELF) = max over the bounds of V_st / R_I = {:.4g} {}, V_st = V_b (W_s / "
               "W)^(1 - 2.5 beta_M) (ASCE 7-16 Eqs. 17.5-7, 17.5-8; W_s {:.5g} {}, W {:.5g} {}, "
               "R_I {:g}):",
               s->elf, u.force(), s->structure_weight, u.force(), s->weight, u.force(), s->r_i);
    for (std::size_t b = 0; b < o.bounds.size(); ++b) {
      fmt::print(md, "{}{} V_st {:.4g} {}", b == 0 ? " " : ", ", o.bounds[b].bound, s->v_st[b],
                 u.force());
    }
    fmt::print(md,
               ". The limits of 17.5.4.3 (the fixed-base force of section 12.8 at T_M, the wind "
               "shear, the force that activates the isolation) are not checked: the design file "
               "does not give their inputs.\n");
  } else if (design.code == model::DesignCode::kAsce7_16) {
    fmt::print(md,
               "\nV_s of the structure above the isolation (ASCE 7-16 17.5.4.2) is not "
               "computed: the design file gives no `r_i`{}.\n",
               o.structure_weight > 0.0 ? "" : " (and the model has no stories)");
  } else {
    fmt::print(md,
               "\nThe design forces of the structure above the isolation by EN 1998-1 "
               "section 10 are not computed here: its rules are not at hand.\n");
  }
}

void WriteChecksSection(const DesignOutcome& o, std::ostream& md) {
  fmt::print(md, "\n## Checks\n\n");
  fmt::print(md,
             "| check | clause | demand | limit | basis | verdict |\n|---|---|---|---|---|---|\n");
  for (const DesignCheck& check : o.checks.checks) {
    fmt::print(md, "| {} | {} | {} | {} | {} | {} |\n", check.check, check.clause,
               Amount(check.demand, check.unit), Amount(check.limit, check.unit), check.basis,
               VerdictName(check.verdict));
  }
}

// The figures, or where the figures are not drawn here, the command that draws them.
void WriteFiguresSection(const DesignOutcome& o, const std::string& directory, bool figures,
                         std::ostream& md) {
  fmt::print(md, "\n## Figures\n\n");
  if (!figures) {
    fmt::print(md, "Not drawn here: `scripts/plot_design.py {}` draws them from this folder.\n",
               directory);
    return;
  }
  fmt::print(md,
             "Histories kept for record {}{} (the largest D_TM of the governing bound), each "
             "bound in its worst eccentricity case: `{}`.\n\n",
             o.records[o.figure_record].name,
             o.orientations.size() > 1
                 ? fmt::format(" at {:g} degrees", o.orientations[o.figure_orientation])
                 : "",
             fmt::join(o.history_files, "`, `"));
  fmt::print(md, "![The worst bearing's loops at the three bounds](design_loops.png)\n\n");
  if (o.study.directions == 2) {
    fmt::print(md, "![The orbits of the bearings that move most and least](design_orbits.png)\n\n");
  }
  if (!std::isnan(o.values[0][IndexOf(DesignQuantity::kStoryDriftRatio)].value)) {
    fmt::print(md, "![Peak story drift ratios](design_drifts.png)\n");
  }
}

void WriteReport(const model::DesignFile& design, const DesignOutcome& o,
                 const std::string& directory, bool figures, std::ostream& md) {
  const UnitSystem& u = design.model.units;
  const bool eurocode = design.code == model::DesignCode::kEn1998_1;
  fmt::print(md, "# Isolation design: {}\n\n",
             design.description.empty() ? fs::path(design.model_path).stem().string()
                                        : design.description);
  fmt::print(md,
             "Model `{}`, design file `{}`. Code: {}, {}. Target: {}. Lengths in {}, forces in "
             "{}.\n\n",
             design.model_path, design.path, model::CodeName(design.code),
             eurocode ? "section 10 (base isolation)"
                      : "chapter 17 (seismically isolated "
                        "structures)",
             spectra::Describe(design.target), u.length(), u.force());
  if (!o.warnings.empty()) fmt::print(md, "**{}**\n\n", WarningNote(o));
  WriteSummary(design, o, md);
  WriteBoundModels(design, o, directory, md);
  WriteElfSection(design, o, md);
  WriteBearingTable(o, u, md);
  WriteBearingWeights(design, o, md);
  WriteSuiteSection(design, o, figures, md);
  WriteResponseHistoryValues(design, o, md);
  WriteWarningsSection(o, md);
  WriteDesignValues(design, o, md);
  WriteChecksSection(o, md);
  WriteFiguresSection(o, directory, figures, md);
}

}  // namespace

void WriteDesignFiles(const model::DesignFile& design, const DesignOutcome& outcome,
                      const std::string& output_directory, bool figures) {
  const fs::path dir(output_directory);
  io::WriteTextFileAtomically((dir / "design_values.csv").string(),
                              [&](std::ostream& f) { WriteValues(design, outcome, f); });
  io::WriteTextFileAtomically((dir / "design_runs.csv").string(),
                              [&](std::ostream& f) { WriteRuns(design, outcome, dir, f); });
  io::WriteTextFileAtomically((dir / "design_checks.csv").string(),
                              [&](std::ostream& f) { WriteChecks(outcome, f); });
  io::WriteTextFileAtomically((dir / "design_parts.csv").string(),
                              [&](std::ostream& f) { WriteParts(design, outcome, f); });
  io::WriteTextFileAtomically((dir / "design_bearings.csv").string(),
                              [&](std::ostream& f) { WriteBearings(design, outcome, f); });
  io::WriteTextFileAtomically((dir / "design_spectra.csv").string(),
                              [&](std::ostream& f) { WriteSpectra(outcome, f); });
  io::WriteTextFileAtomically((dir / "design.md").string(), [&](std::ostream& f) {
    WriteReport(design, outcome, output_directory, figures, f);
  });
}

std::string DesignSummaryText(const model::DesignFile& design, const DesignOutcome& o) {
  const UnitSystem& u = design.model.units;
  std::ostringstream out;
  if (!o.warnings.empty()) fmt::print(out, "{}\n", WarningNote(o));
  fmt::print(out, "design values ({}):\n", StatisticText(o));
  fmt::print(out, "{:<54}", "");
  for (const DesignBound& b : o.bounds) fmt::print(out, " {:>12}", b.bound);
  fmt::print(out, "  governing\n");
  for (const DesignQuantityInfo& info : DesignQuantities()) {
    fmt::print(out, "{:<54}", fmt::format("{} ({})", info.label, UnitOf(info.quantity, u)));
    for (std::size_t b = 0; b < o.bounds.size(); ++b) {
      fmt::print(out, " {:>12.5g}", o.values[b][IndexOf(info.quantity)].value);
    }
    fmt::print(out, "  {}\n", o.bounds[o.governing[IndexOf(info.quantity)]].bound);
  }
  const DesignChecks& c = o.checks;
  fmt::print(out, "{}\n", DesignValueText("D_TM", c.total_displacement, o, u.length()));
  fmt::print(out, "{}\n", DesignValueText("V_b", c.base_shear, o, u.force()));
  if (c.superstructure) {
    fmt::print(out, "{}\n", DesignValueText("V_s", c.superstructure->v_s, o, u.force()));
  }
  fmt::print(out, "checks ({}):\n", model::CodeName(design.code));
  for (const DesignCheck& check : c.checks) {
    fmt::print(out, "  {}: {} against {} ({}; {}): {}\n", check.check,
               Amount(check.demand, check.unit), Amount(check.limit, check.unit), check.basis,
               check.clause, VerdictName(check.verdict));
  }
  if (!o.warnings.empty()) fmt::print(out, "warnings:\n");
  for (const std::string& line : WarningLines(o)) fmt::print(out, "  {}\n", line);
  return out.str();
}

}  // namespace isolab::study
