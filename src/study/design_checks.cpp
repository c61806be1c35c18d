#include "isolab/study/design_checks.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "isolab/study/design.h"

namespace isolab::study {
namespace {

using model::DesignCode;

// The governing bound's response-history value of `q`, and the largest ELF value over the bounds.
DesignValue FromResponseHistory(const DesignOutcome& o, DesignQuantity q, double elf) {
  DesignValue v;
  v.bound = o.governing[IndexOf(q)];
  v.response_history = o.values[v.bound][IndexOf(q)].value;
  v.elf = elf;
  return v;
}

DesignValue TotalDisplacement(const model::DesignFile& design, const DesignOutcome& o) {
  double elf = 0.0;
  for (const DesignBound& b : o.bounds) elf = std::max(elf, b.elf_total_displacement);
  DesignValue v = FromResponseHistory(o, DesignQuantity::kTotalDisplacement, elf);
  if (design.code == DesignCode::kEn1998_1) {
    v.factor = design.gamma_x;
    v.rule = fmt::format("gamma_x {:g} x the response history's, EN 1998-1 10.3(2)", v.factor);
  } else {
    v.floor = kElfDisplacementFloor;
    v.rule = fmt::format("not below {:g} D_TM (ELF), ASCE 7-16 17.6.3", v.floor);
  }
  v.value = std::max(v.factor * v.response_history, v.floor * v.elf);
  return v;
}

DesignValue BaseShear(const model::DesignFile& design, const DesignOutcome& o) {
  double elf = 0.0;
  for (const DesignBound& b : o.bounds) elf = std::max(elf, b.elf.base_shear);
  DesignValue v = FromResponseHistory(o, DesignQuantity::kBaseShear, elf);
  if (design.code == DesignCode::kEn1998_1) {
    v.rule = "the response history's, EN 1998-1 4.3.3.4.3";
  } else {
    v.floor = kElfShearFloor;
    v.rule = fmt::format("not below {:g} V_b (ELF), ASCE 7-16 17.6.3", v.floor);
  }
  v.value = std::max(v.response_history, v.floor * v.elf);
  return v;
}

std::optional<SuperstructureShear> Superstructure(const model::DesignFile& design,
                                                  const DesignOutcome& o) {
  if (design.code != DesignCode::kAsce7_16 || design.r_i <= 0.0 || o.structure_weight <= 0.0) {
    return std::nullopt;
  }
  SuperstructureShear s;
  s.r_i = design.r_i;
  s.structure_weight = o.structure_weight;
  s.weight = o.building_weight;
  for (const DesignBound& b : o.bounds) {
    const double exponent = 1.0 - 2.5 * b.elf.at_design.damping;
    s.v_st.push_back(b.elf.base_shear * std::pow(s.structure_weight / s.weight, exponent));
    s.elf = std::max(s.elf, s.v_st.back() / s.r_i);
  }
  // The first story's shear, design values per bound (the parts' first story_shear).
  DesignValue& v = s.v_s;
  v.response_history = -INFINITY;
  for (const DesignPartValue& part : o.parts) {
    if (part.quantity != PartQuantity::kStoryShear) continue;
    for (std::size_t b = 0; b < part.bounds.size(); ++b) {
      if (part.bounds[b].value > v.response_history) {
        v.response_history = part.bounds[b].value;
        v.bound = b;
      }
    }
    break;
  }
  v.factor = 1.0 / s.r_i;
  v.floor = 0.8;
  v.elf = s.elf;
  v.value = std::max(v.factor * v.response_history, v.floor * v.elf);
  v.rule = fmt::format(
      "the first story's shear / R_I {:g}, not below 0.8 V_s (ELF), ASCE 7-16 17.6.3 as read "
      "here (a lower floor the edition may allow a regular structure is not taken: check it); "
      "17.5.4.3's limits not checked",
      s.r_i);
  return s;
}

DesignCheck DriftCheck(const model::DesignFile& design, const DesignOutcome& o) {
  DesignCheck c;
  const std::size_t d = o.governing[IndexOf(DesignQuantity::kStoryDriftRatio)];
  c.check = "story drift ratio <= drift_limit";
  c.clause = design.code == DesignCode::kEn1998_1
                 ? "the design's drift_limit at the design action, informative (EN 1998-1 "
                   "4.4.3.2 limits drifts under the damage-limitation action, not run here)"
                 : "ASCE 7-16 17.6.4.4";
  c.unit = "%";
  c.demand = o.values[d][IndexOf(DesignQuantity::kStoryDriftRatio)].value;
  c.limit = 100.0 * design.drift_limit;
  if (std::isnan(c.demand)) {
    c.basis = "no story has a height";
    return c;
  }
  c.basis = fmt::format("{} bound", o.bounds[d].bound);
  c.verdict = c.demand <= c.limit ? Verdict::kMet : Verdict::kExceeded;
  return c;
}

// One check per group of isolators that share a capacity (and its basis), in the order first met.
std::vector<DesignCheck> CapacityChecks(const model::DesignFile& design, const DesignOutcome& o,
                                        double demand) {
  std::vector<DesignCheck> checks;
  std::vector<std::optional<BearingCapacity>> capacities;
  for (const IsolatorCapacity& c : o.capacities) {
    const auto same = std::find_if(capacities.begin(), capacities.end(), [&](const auto& k) {
      return k.has_value() == c.capacity.has_value() &&
             (!k || (k->displacement == c.capacity->displacement && k->basis == c.capacity->basis));
    });
    if (same != capacities.end()) {
      checks[static_cast<std::size_t>(same - capacities.begin())].isolators.push_back(c.isolator);
      continue;
    }
    capacities.push_back(c.capacity);
    DesignCheck check;
    check.clause = design.code == DesignCode::kEn1998_1 ? "EN 1998-1 10.3(2)" : "ASCE 7-16 17.2.4";
    check.unit = design.model.units.length();
    check.demand = demand;
    check.isolators = {c.isolator};
    if (c.capacity) {
      check.limit = c.capacity->displacement;
      check.basis = c.capacity->basis;
      check.verdict = demand <= check.limit ? Verdict::kMet : Verdict::kExceeded;
    } else {
      check.basis =
          "not known from the laws (a single pendulum or a lead-rubber bearing states none; an "
          "HDR bearing's needs shear_strain_limit)";
    }
    checks.push_back(std::move(check));
  }
  for (DesignCheck& check : checks) {
    check.check =
        fmt::format("D_TM <= displacement capacity of {}", fmt::join(check.isolators, ", "));
  }
  return checks;
}

// Each bearing's least axial load over every run of every bound, case, record and orientation.
std::vector<DesignCheck> UpliftChecks(const model::DesignFile& design, const DesignOutcome& o) {
  std::vector<DesignCheck> checks;
  for (const DesignPartValue& part : o.parts) {
    if (part.quantity != PartQuantity::kLeastAxialLoad) continue;
    DesignCheck check;
    check.check = fmt::format("least axial load of {} > 0 (no uplift)", part.part);
    check.clause = design.code == DesignCode::kEn1998_1
                       ? "EN 1998-1 section 10 (its uplift clause is not at hand here)"
                       : "ASCE 7-16 17.2.4.7";
    check.unit = design.model.units.force();
    check.limit = 0.0;
    check.isolators = {part.part};
    check.demand = INFINITY;
    std::size_t lifted = 0;
    for (const JobResult& run : o.runs) {
      for (const PartPeak& peak : run.parts) {
        if (peak.quantity != part.quantity || peak.part != part.part) continue;
        check.demand = std::min(check.demand, peak.value);
        if (peak.value <= 0.0) ++lifted;
      }
    }
    // Without overturning the loads are the static shares (moved by the eccentricity cases):
    // a bearing that lifts off under them is a finding, one that does not is not yet checked.
    const bool overturning = design.model.axial_load && design.model.axial_load->overturning;
    if (lifted > 0) {
      check.verdict = Verdict::kExceeded;
      check.basis = fmt::format(
          "lifts off in {} of the {} runs: local uplift is allowed only "
          "where the isolator is shown to take it",
          lifted, o.runs.size());
    } else if (overturning) {
      check.verdict = Verdict::kMet;
      check.basis = fmt::format("the least over all {} runs", o.runs.size());
    } else {
      check.basis = fmt::format(
          "the least static share over all {} runs: the model's axial_load has no overturning, "
          "so the overturning that lifts bearings is not modelled (axial_load: {{overturning: "
          "true}})",
          o.runs.size());
    }
    checks.push_back(std::move(check));
  }
  return checks;
}

}  // namespace

std::string_view VerdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::kMet:
      return "met";
    case Verdict::kExceeded:
      return "EXCEEDED";
    case Verdict::kNotChecked:
      return "not checked";
  }
  return "";
}

DesignChecks CheckDesign(const model::DesignFile& design, const DesignOutcome& o) {
  DesignChecks c;
  c.code = design.code;
  c.total_displacement = TotalDisplacement(design, o);
  c.base_shear = BaseShear(design, o);
  c.superstructure = Superstructure(design, o);
  c.checks.push_back(DriftCheck(design, o));
  for (DesignCheck& check : CapacityChecks(design, o, c.total_displacement.value)) {
    c.checks.push_back(std::move(check));
  }
  for (DesignCheck& check : UpliftChecks(design, o)) c.checks.push_back(std::move(check));
  return c;
}

}  // namespace isolab::study
