#include "isolab/study/design.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>

#include "isolab/analysis/synthetic_motion.h"
#include "isolab/core/errors.h"
#include "isolab/design/matched_pairs.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/record.h"
#include "isolab/model/bounds.h"
#include "isolab/model/build_structure.h"
#include "isolab/model/opensees_export.h"
#include "isolab/spectra/rotd_spectrum.h"
#include "isolab/study/run_job.h"

namespace isolab::study {
namespace {

namespace fs = std::filesystem;
constexpr double kDamping = 0.05;
constexpr double kCyclesOfLongestPeriod = 4.0;  // a synthetic record holds 4 of its longest period
constexpr double kDisplayLow = 0.05;  // s: the report's spectra from here to twice the range's top
constexpr int kDisplayPoints = 80;
constexpr double kAbsent = std::numeric_limits<double>::quiet_NaN();

constexpr DesignQuantityInfo kDesignQuantities[] = {
    {DesignQuantity::kDisplacement, "D_M", "maximum displacement D_M (centre of mass)"},
    {DesignQuantity::kTotalDisplacement, "D_TM", "total maximum displacement D_TM (worst bearing)"},
    {DesignQuantity::kBaseShear, "V_b", "base shear V_b"},
    {DesignQuantity::kIsolatorForce, "isolator_force", "largest isolator force"},
    {DesignQuantity::kStoryDriftRatio, "story_drift_ratio", "story drift ratio"},
    {DesignQuantity::kFloorAcceleration, "floor_acceleration", "floor acceleration"},
    {DesignQuantity::kResidualDisplacement, "residual_displacement",
     "residual isolator displacement"},
};
static_assert(std::size(kDesignQuantities) == kDesignQuantityCount);

}  // namespace

Quantity SourceOf(DesignQuantity q) {
  switch (q) {
    case DesignQuantity::kDisplacement:
      return Quantity::kBaseCentreDisplacement;
    case DesignQuantity::kTotalDisplacement:
      return Quantity::kIsolatorDisplacement;
    case DesignQuantity::kBaseShear:
      return Quantity::kBaseShear;
    case DesignQuantity::kIsolatorForce:
      return Quantity::kIsolatorForce;
    case DesignQuantity::kStoryDriftRatio:
      return Quantity::kStoryDriftRatio;
    case DesignQuantity::kFloorAcceleration:
      return Quantity::kFloorAcceleration;
    case DesignQuantity::kResidualDisplacement:
      return Quantity::kResidualIsolatorDisplacement;
  }
  return Quantity::kIsolatorDisplacement;
}

namespace {

// A record's spectrum at `periods` (g): a pair's RotD100 (ASCE 7-16 17.3.3), or with
// `components` the mean of its components' 5 % spectra (EN 1998-1 3.2.3.1.2(4) takes each
// horizontal component as a time history of the suite); one record's 5 % Sa; with its entry's
// scale. Throws InputError naming the entry for a record too short for the range's top period
// `top` (s): its spectrum there is not a record's but its length's.
std::vector<double> RecordSpectrum(const model::StudyRecord& record,
                                   const std::vector<io::Record>& read,
                                   const std::vector<double>& periods, double top,
                                   bool components) {
  std::vector<integrators::SampledHistory> histories;
  for (std::size_t k = 0; k < record.components.size(); ++k) {
    const model::GroundMotionSection& c = record.components[k];
    const io::Record& r = read[k];
    const double duration = r.dt * static_cast<double>(r.values.size() - 1);
    if (duration < kCyclesOfLongestPeriod * top) {
      throw InputError({record.entry},
                       fmt::format("'{}' lasts {:g} s, less than {:g} cycles of the scaling "
                                   "range's top period {:.3g} s: too short for the range (give a "
                                   "longer record, or a narrower period_range)",
                                   c.file, duration, kCyclesOfLongestPeriod, top));
    }
    const double in_g =
        UnitSystem("N", "m", "s").Convert(1.0, r.units, dimension::kAcceleration) / 9.80665;
    integrators::SampledHistory h{r.dt, r.values};
    for (double& v : h.values) v *= in_g * c.scale;
    histories.push_back(std::move(h));
  }
  const std::vector<double> damping = {kDamping};
  std::vector<double> sa;
  if (histories.size() == 2 && components) {
    sa.assign(periods.size(), 0.0);
    for (const integrators::SampledHistory& h : histories) {
      const spectra::ElasticSpectrum s = spectra::ComputeElasticSpectrum(h, periods, damping);
      for (std::size_t p = 0; p < periods.size(); ++p) {
        sa[p] += s.at(0, p).pseudo_acceleration / static_cast<double>(histories.size());
      }
    }
  } else if (histories.size() == 2) {
    const spectra::PairSpectrum s =
        spectra::ComputePairSpectrum(histories[0], histories[1], periods, damping);
    for (std::size_t p = 0; p < periods.size(); ++p) {
      sa.push_back(s.rotd100.at(0, p).pseudo_acceleration);
    }
  } else {
    const spectra::ElasticSpectrum s =
        spectra::ComputeElasticSpectrum(histories[0], periods, damping);
    for (std::size_t p = 0; p < periods.size(); ++p) sa.push_back(s.at(0, p).pseudo_acceleration);
  }
  return sa;
}

// A record's peak ground acceleration (g) with its entry's scale, a pair's the mean of its
// components' (EN 1998-1 3.2.3.1.2(4)b: each horizontal component a time history of the suite).
double RecordPeakAcceleration(const model::StudyRecord& record,
                              const std::vector<io::Record>& read) {
  double sum = 0.0;
  for (std::size_t k = 0; k < record.components.size(); ++k) {
    const io::Record& r = read[k];
    const double in_g = record.components[k].scale *
                        UnitSystem("N", "m", "s").Convert(1.0, r.units, dimension::kAcceleration) /
                        9.80665;
    double peak = 0.0;
    for (const double a : r.values) peak = std::max(peak, std::abs(in_g * a));
    sum += peak;
  }
  return sum / static_cast<double>(record.components.size());
}

// Synthetic pairs matched to the target over [0.1 s, 1.5 x the scaling range's top], written as
// AT2 files in <output>/records; H1 alone for a building in one direction.
std::vector<model::StudyRecord> SyntheticRecords(
    const model::DesignFile& design, double top, const std::string& output_directory,
    int directions, std::vector<double>* misfits,
    const std::function<void(const std::string&)>& progress) {
  const model::SyntheticSuite& s = *design.synthetic;
  design::MatchedPairSpec spec;
  spec.seed = s.seed;
  spec.count = s.count;
  spec.motion.duration = s.duration;
  spec.motion.dt = s.dt;
  spec.period_min = std::max(0.1, 5.0 * s.dt);
  spec.period_max = std::min(1.5 * top, s.duration / kCyclesOfLongestPeriod);
  if (design.code == model::DesignCode::kEn1998_1) {
    spec.period_max = std::min(spec.period_max, spectra::kEurocode8LastPeriod);
  }
  spec.tolerance = s.tolerance;
  spec.target_name = spectra::Describe(design.target);
  if (spec.period_max < top) {
    throw InputError(
        {design.suite_key + ".synthetic.duration"},
        fmt::format("{:g} s records cannot hold {:g} cycles of the scaling range's "
                    "top period {:g} s (give a duration of at least {:g} s)",
                    s.duration, kCyclesOfLongestPeriod, top, kCyclesOfLongestPeriod * top));
  }
  if (progress) {
    progress(fmt::format("suite: matching {} synthetic pairs to the target over {:g} to {:g} s",
                         s.count, spec.period_min, spec.period_max));
  }
  const std::vector<design::MatchedPair> pairs = design::MatchPairs(spec, [&design](double t) {
    return spectra::ContinuedSpectralAcceleration(design.target, t);
  });
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (!pairs[k].converged) {
      throw InputError({design.suite_key + ".synthetic"},
                       fmt::format("pair {} matched the target only to {:.3g} after {} iterations "
                                   "(tolerance {:g}: raise it, or give a longer duration)",
                                   k + 1, pairs[k].misfit, pairs[k].iterations, s.tolerance));
    }
  }
  const fs::path folder = fs::path(output_directory) / "records";
  fs::create_directories(folder);
  const int width = static_cast<int>(std::to_string(s.count).size());
  std::vector<model::StudyRecord> records;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    model::StudyRecord record;
    record.name = fmt::format("pair{:0{}}", k + 1, width);
    record.entry = fmt::format("{} (synthetic {})", design.suite_key, record.name);
    const io::Record* components[] = {&pairs[k].h1, &pairs[k].h2};
    for (int c = 0; c < directions; ++c) {
      model::GroundMotionSection section;
      section.file = (folder / fmt::format("{}_h{}.at2", record.name, c + 1)).string();
      analysis::WriteAt2(*components[c], section.file);
      record.components.push_back(section);
    }
    records.push_back(std::move(record));
    misfits->push_back(pairs[k].misfit);
  }
  return records;
}

// The suite's records as read, each checked against the model's analysis step (a run may refine
// a record's step, never coarsen it): refused before any work, naming the entry.
std::vector<std::vector<io::Record>> ReadSuite(const std::vector<model::StudyRecord>& records,
                                               const model::ModelFile& model) {
  const double to_seconds = model.units.SiFactor(dimension::kTime);
  std::vector<std::vector<io::Record>> read;
  for (const model::StudyRecord& record : records) {
    read.emplace_back();
    for (const model::GroundMotionSection& c : record.components) {
      io::Record r =
          io::ReadRecord(c.file, {c.units, c.dt * to_seconds, record.entry, record.entry});
      if (r.dt < model.analysis.dt * to_seconds * (1 - 1e-12)) {
        throw InputError(
            {record.entry},
            fmt::format("'{}' is sampled at {:g} s, finer than the model's "
                        "analysis.dt {:g} s: a run cannot take a record on a "
                        "coarser step than its own (give analysis.dt <= {:g} s in "
                        "'{}')",
                        c.file, r.dt, model.analysis.dt * to_seconds, r.dt, model.path));
      }
      if (std::all_of(r.values.begin(), r.values.end(), [](double a) { return a == 0.0; })) {
        throw InputError({record.entry}, fmt::format("'{}' is all zeros: it has no spectrum to "
                                                     "scale to the target",
                                                     c.file));
      }
      read.back().push_back(std::move(r));
    }
  }
  return read;
}

// A quantity a model does not have (a drift without story heights) is NaN for every record, and
// stays NaN: never 0. `least`: the most unfavourable record is the least (a least axial load).
DesignStatistic SuiteStatistic(std::vector<double> per_record, bool mean_of_suite,
                               bool least = false) {
  DesignStatistic s;
  s.per_record = std::move(per_record);
  double sum = 0.0;
  s.max =
      least ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  for (const double v : s.per_record) {
    sum += v;
    s.max = least ? std::min(s.max, v) : std::max(s.max, v);
  }
  if (std::isnan(sum)) s.max = kAbsent;
  s.mean = sum / static_cast<double>(s.per_record.size());
  s.value = mean_of_suite ? s.mean : s.max;
  return s;
}

}  // namespace

std::string BearingWeightRule(const model::ModelFile& model, const DesignOutcome& out) {
  double law = 0.0, carried = 0.0, low = INFINITY, high = -INFINITY;
  std::size_t pendulums = 0;
  for (const design::IsolationSystem::BearingWeight& w : out.bearing_weights) {
    if (std::isnan(w.carried)) continue;
    ++pendulums;
    law += w.law;
    carried += w.carried;
    low = std::min(low, w.carried);
    high = std::max(high, w.carried);
  }
  if (pendulums == 0) return "";
  const std::string force = model.units.force();
  return fmt::format(
      "bearing weights: {} pendulum bearing{} carry {:.5g} {} in all ({:.4g} to {:.4g} {} each) "
      "in the ELF step and the runs alike, {}; the building weighs {:.5g} {}",
      pendulums, pendulums == 1 ? "" : "s", carried, force, low, high, force,
      model.axial_load
          ? fmt::format("their static shares of the weight under axial_load (rigid-slab "
                        "statics; their laws' w sum to {:.5g} {})",
                        law, force)
          : "their laws' w (no axial_load)",
      out.building_weight, force);
}

namespace {

// Each isolator's displacement capacity: a plan model's isolators, or a one-direction layer's
// bearing type (every bearing alike).
std::vector<IsolatorCapacity> Capacities(const model::ModelFile& model, double strain_limit) {
  std::vector<IsolatorCapacity> capacities;
  if (const auto* sites = model::PlanIsolators(model)) {
    for (const structure::PlanIsolatorSite& site : *sites) {
      capacities.push_back({site.name, DisplacementCapacity(site.assembly, strain_limit)});
    }
  } else {
    capacities.push_back(
        {"every bearing of the layer", DisplacementCapacity(model.isolation, strain_limit)});
  }
  return capacities;
}

// One bound's envelope per record over its runs: over the first `cases` eccentricity cases and
// every orientation, the largest `value` of a run (the least with `least`); NaN where no run of
// the record has one.
template <class RunValue>
std::vector<double> RecordEnvelopes(const DesignOutcome& out, std::size_t b, std::size_t cases,
                                    bool least, const RunValue& value) {
  std::vector<double> per_record(out.records.size(), kAbsent);
  for (std::size_t r = 0; r < per_record.size(); ++r) {
    double& e = per_record[r];
    for (std::size_t c = 0; c < cases; ++c) {
      for (std::size_t o = 0; o < out.orientations.size(); ++o) {
        const double v = value(out.RunOf(b, c, r, o));
        if (std::isnan(v)) continue;
        e = std::isnan(e) ? v : least ? std::min(e, v) : std::max(e, v);
      }
    }
  }
  return per_record;
}

// The bound whose value governs: the largest (the least with `least`). A NaN never governs: a
// number replaces it, and it replaces nothing.
template <class BoundValue>
std::size_t GoverningBound(std::size_t bounds, bool least, const BoundValue& value) {
  std::size_t governing = 0;
  for (std::size_t b = 1; b < bounds; ++b) {
    const double v = value(b), g = value(governing);
    if ((least ? v < g : v > g) || (std::isnan(g) && !std::isnan(v))) governing = b;
  }
  return governing;
}

// The headline design values per bound, each the envelope over the cases and orientations (D_M,
// the base's displacement, without eccentricity), then over the suite; and the governing bounds.
void HeadlineValues(DesignOutcome& out) {
  for (std::size_t b = 0; b < out.bounds.size(); ++b) {
    std::array<DesignStatistic, kDesignQuantityCount> values;
    for (const DesignQuantityInfo& info : kDesignQuantities) {
      const std::size_t q = static_cast<std::size_t>(SourceOf(info.quantity));
      const std::size_t cases =
          info.quantity == DesignQuantity::kDisplacement ? 1 : out.eccentricities.size();
      values[static_cast<std::size_t>(info.quantity)] =
          SuiteStatistic(RecordEnvelopes(out, b, cases, false,
                                         [q](const JobResult& run) { return run.values[q]; }),
                         out.mean_of_suite);
    }
    out.values.push_back(values);
  }
  for (std::size_t q = 0; q < kDesignQuantityCount; ++q) {
    out.governing[q] = GoverningBound(out.bounds.size(), false,
                                      [&](std::size_t b) { return out.values[b][q].value; });
  }
}

// Every part's design values, as the headline ones.
std::vector<DesignPartValue> PartValues(const DesignOutcome& out) {
  std::vector<DesignPartValue> parts;
  // The parts as the first run lists them: every run of a bound has the same; the bounds too.
  for (const PartPeak& p : out.runs.front().parts) parts.push_back({p.quantity, p.part, {}, 0});
  for (std::size_t k = 0; k < parts.size(); ++k) {
    DesignPartValue& part = parts[k];
    const bool least = part.quantity == PartQuantity::kLeastAxialLoad;
    // Every run of a design has the same parts in the same order; looked up by name where a
    // run's differ.
    const auto value = [&](const JobResult& run) {
      const auto same = [&](const PartPeak& p) {
        return p.part == part.part && p.quantity == part.quantity;
      };
      const auto found = k < run.parts.size() && same(run.parts[k])
                             ? run.parts.begin() + static_cast<std::ptrdiff_t>(k)
                             : std::find_if(run.parts.begin(), run.parts.end(), same);
      return found != run.parts.end() ? found->value : kAbsent;
    };
    for (std::size_t b = 0; b < out.bounds.size(); ++b) {
      part.bounds.push_back(
          SuiteStatistic(RecordEnvelopes(out, b, out.eccentricities.size(), least, value),
                         out.mean_of_suite, least));
    }
    part.governing = GoverningBound(out.bounds.size(), least,
                                    [&](std::size_t b) { return part.bounds[b].value; });
  }
  return parts;
}

// Every run's warnings, once per bound with the count of the bound's runs that gave each.
std::vector<DesignWarning> CollectWarnings(const DesignOutcome& out) {
  std::vector<DesignWarning> warnings;
  const std::size_t per_bound = out.RunsPerBound();
  for (std::size_t b = 0; b < out.bounds.size(); ++b) {
    const std::size_t first = warnings.size();
    for (std::size_t j = b * per_bound; j < (b + 1) * per_bound; ++j) {
      for (const std::string& text : out.runs[j].warnings) {
        const auto same =
            std::find_if(warnings.begin() + static_cast<std::ptrdiff_t>(first), warnings.end(),
                         [&text](const DesignWarning& w) { return w.text == text; });
        if (same != warnings.end()) {
          ++same->runs;
        } else {
          warnings.push_back({b, text, 1});
        }
      }
    }
  }
  return warnings;
}

}  // namespace

std::span<const DesignQuantityInfo> DesignQuantities() { return kDesignQuantities; }

std::unique_ptr<DesignFolder> ClaimDesignFolder(const std::string& requested,
                                                const model::DesignFile& design,
                                                const std::string& option) {
  const std::string folder = !requested.empty() ? requested
                             : !design.output_directory.empty()
                                 ? design.output_directory
                                 : fs::path(design.path).stem().string();
  std::vector<DesignInput> records;
  for (const model::StudyRecord& record : design.records) {
    for (const model::GroundMotionSection& c : record.components) {
      records.push_back({c.file, record.entry});
    }
  }
  return std::make_unique<DesignFolder>(folder, requested.empty() ? "output.directory" : option,
                                        records);
}

namespace {

using Progress = std::function<void(const std::string&)>;

void Tell(const Progress& progress, const std::string& line) {
  if (progress) progress(line);
}

// 1. The bound models, read as they will run, into out.bounds (to be written once the suite is
// ready, so that a design refused on its suite leaves nothing behind).
model::BoundModels ReadBoundModels(const model::DesignFile& design, const fs::path& models,
                                   DesignOutcome& out) {
  model::BoundModels bounds = model::MakeBoundModels(design.model);
  out.modified = bounds.properties;
  const std::string stem = fs::path(design.model_path).stem().string();
  for (const model::BoundModel& bound : bounds.models) {
    DesignBound b;
    b.bound = bound.bound;
    b.model_file = (models / (stem + "_" + bound.bound + ".yaml")).string();
    b.model = model::LoadModelText(bound.text, b.model_file);
    const model::OpenSeesExport exported =
        model::ExportToOpenSees(b.model, fmt::format("{} bound of {} (isolab design {})",
                                                     bound.bound, design.model_path, design.path));
    if (!exported.refused.empty() && out.opensees_refused.empty()) {
      out.opensees_refused = fmt::format("the {} bound: {}", bound.bound, exported.refused);
    }
    b.opensees_text = exported.tcl;
    b.opensees_file = (models / (stem + "_" + bound.bound + ".tcl")).string();
    out.bounds.push_back(std::move(b));
  }
  // Every bound exported, or none: a design's bounds go to OpenSees together.
  if (!out.opensees_refused.empty()) {
    for (DesignBound& b : out.bounds) {
      b.opensees_file.clear();
      b.opensees_text.clear();
    }
  }
  return bounds;
}

// The nominal bound's building: its capacities and the weights its bearings carry.
void DescribeNominalBuilding(const model::DesignFile& design, const design::IsolationSystem& system,
                             const DesignBound& b, DesignOutcome& out, const Progress& progress) {
  out.capacities = Capacities(b.model, design.shear_strain_limit);
  out.bearing_weights = system.bearing_weights();
  out.building_weight = system.weight();
  const structure::LaidOutStructure laid = model::BuildStructure(b.model);
  if (laid.layout.isolated() && !laid.layout.stories.empty()) {
    const int base = laid.layout.levels.front().dofs[structure::kX];
    out.structure_weight = system.weight() - laid.structure.mass()[base] * system.gravity();
  }
  if (const std::string rule = BearingWeightRule(design.model, out); !rule.empty()) {
    Tell(progress, rule);
  }
}

// 2. The ELF procedure on each bound.
void SolveBoundsByElf(const model::DesignFile& design, DesignOutcome& out,
                      const Progress& progress) {
  const UnitSystem& units = design.model.units;
  const double second = 1.0 / units.SiFactor(dimension::kTime);
  const double metre = units.Convert(1.0, "m", dimension::kLength);
  const design::DisplacementDemand demand = design::CodeDemand(design.target, units);
  for (DesignBound& b : out.bounds) {
    const design::IsolationSystem system(b.model);
    try {
      b.elf = design::SolveElf(system, demand, metre);
    } catch (const std::runtime_error& error) {
      if (dynamic_cast<const InputError*>(&error)) throw;
      // The fixed point does not exist for this target and isolation system: an input's fault
      // (a target far too weak or strong for the bearings), located at the target.
      throw InputError({design.target_key},
                       fmt::format("the ELF procedure on the {} bound: {}", b.bound, error.what()));
    }
    b.damping_coefficient = design::CodeDampingCoefficient(design.target, b.elf.at_design.damping);
    b.elf_total_displacement = design::TotalDisplacement(b.model, system, b.elf);
    b.bearings = system.BearingProperties(b.elf.displacement, b.elf.period);
    Tell(progress, fmt::format("ELF {}: D_M {:.4g} {}, T_M {:.4g} s, beta_M {:.3g}, B_M {:.3g}",
                               b.bound, b.elf.displacement, units.length(), b.elf.period / second,
                               b.elf.at_design.damping, b.damping_coefficient));
    if (b.bound == "nominal") DescribeNominalBuilding(design, system, b, out, progress);
  }
}

// The scaling range (s) from the bounds' T_M: from the upper bound's, to the lower bound's; an
// EN 1998-1 range cut at 4 s, where the code's spectrum ends.
void SetScalingRange(const model::DesignFile& design, DesignOutcome& out) {
  const double second = 1.0 / design.model.units.SiFactor(dimension::kTime);
  const auto period_of = [&](const std::string& name) {
    for (const DesignBound& b : out.bounds) {
      if (b.bound == name) return b.elf.period / second;
    }
    return out.bounds.front().elf.period / second;
  };
  out.period_range[0] = design.period_range[0] * period_of("upper");
  out.period_range[1] = design.period_range[1] * period_of("lower");
  if (design.code == model::DesignCode::kEn1998_1 &&
      out.period_range[1] > spectra::kEurocode8LastPeriod) {
    out.uncut_range_top = out.period_range[1];
    out.period_range[1] = spectra::kEurocode8LastPeriod;
  }
}

// The report's periods: the scaling grid, and from 0.05 s to twice its top (Eurocode 8's to 4 s
// at most: beyond it the code gives no spectrum to draw).
std::vector<double> DisplayPeriods(const std::vector<double>& scaling_periods, double top,
                                   bool eurocode) {
  const double display_top =
      eurocode ? std::min(2.0 * top, spectra::kEurocode8LastPeriod) : 2.0 * top;
  std::vector<double> grid = scaling_periods;
  for (int i = 0; i <= kDisplayPoints; ++i) {
    grid.push_back(kDisplayLow *
                   std::pow(display_top / kDisplayLow, static_cast<double>(i) / kDisplayPoints));
  }
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  return grid;
}

// EN 1998-1 3.2.3.1.2(4)b: the suite's mean peak ground acceleration must reach the target's
// a_g S = Se(0) too; where it falls short, the common factor rises until it does.
void RaiseToPeakGroundAcceleration(const model::DesignFile& design,
                                   const std::vector<model::StudyRecord>& records,
                                   const std::vector<std::vector<io::Record>>& suite,
                                   DesignOutcome& out) {
  double sum = 0.0;
  for (std::size_t r = 0; r < records.size(); ++r) {
    sum += out.scaling.factors[r] * RecordPeakAcceleration(records[r], suite[r]);
  }
  out.mean_pga = sum / static_cast<double>(records.size());
  out.pga_floor = spectra::SpectralAcceleration(design.target, 0.0);
  if (out.mean_pga < out.pga_floor) {
    const double raise = out.pga_floor / out.mean_pga;
    out.pga_governs = true;
    out.mean_pga = out.pga_floor;
    out.scaling.common_factor *= raise;
    for (double& f : out.scaling.factors) f *= raise;
    for (double& m : out.scaling.scaled_mean) m *= raise;
  }
}

std::string SuiteLine(const model::DesignFile& design, std::size_t records, int directions,
                      const DesignOutcome& out) {
  const bool eurocode = design.code == model::DesignCode::kEn1998_1;
  return fmt::format(
      "suite: {} {} scaled to {} over {:.3g} to {:.3g} s{} (common factor {:.4g}, governing {})",
      records, directions == 2 ? "pairs" : "records",
      eurocode ? "90 % of the target (EN 1998-1 3.2.3.1.2(4))" : "the target (ASCE 7-16 17.3.3)",
      out.period_range[0], out.period_range[1],
      out.uncut_range_top > 0.0
          ? fmt::format(" (cut from {:.3g} s at 4 s, where the code's spectrum ends)",
                        out.uncut_range_top)
          : "",
      out.scaling.common_factor,
      out.pga_governs ? fmt::format("by the mean PGA {:.4g} g = a_g S", out.pga_floor)
                      : fmt::format("at {:.3g} s", out.scaling.periods[out.scaling.governing]));
}

// 3. The suite, scaled to the target: its records with their scales applied, and in `out` its
// spectra and scaling. A synthetic suite is matched and written first.
std::vector<model::StudyRecord> ScaleSuiteToTarget(
    const model::DesignFile& design, const std::vector<std::vector<io::Record>>& given,
    const std::string& output_directory, DesignOutcome& out, const Progress& progress) {
  const auto suite_start = std::chrono::steady_clock::now();
  const bool eurocode = design.code == model::DesignCode::kEn1998_1;
  const int directions = model::Directions(design.model);
  // The range first: a design refused on it spends no time on a suite and writes nothing.
  std::vector<double> periods;
  try {
    periods = spectra::ScalingPeriods(design.target, out.period_range[0], out.period_range[1]);
  } catch (const InvalidParameter& error) {
    throw InputError({design.suite_key + ".period_range"},
                     fmt::format("{:g} to {:g} s, from T_M of the bounds: {}", out.period_range[0],
                                 out.period_range[1], error.what()));
  }
  std::vector<double> misfits;
  std::vector<model::StudyRecord> records =
      design.synthetic ? SyntheticRecords(design, out.period_range[1], output_directory, directions,
                                          &misfits, progress)
                       : design.records;
  const std::vector<std::vector<io::Record>> suite =
      design.synthetic ? ReadSuite(records, design.model) : given;
  const std::vector<double> grid = DisplayPeriods(periods, out.period_range[1], eurocode);
  std::vector<std::vector<double>> in_range(records.size());
  for (std::size_t r = 0; r < records.size(); ++r) {
    const std::vector<double> sa =
        RecordSpectrum(records[r], suite[r], grid, out.period_range[1], eurocode);
    for (const double t : periods) {
      in_range[r].push_back(sa[std::lower_bound(grid.begin(), grid.end(), t) - grid.begin()]);
    }
    DesignRecord d;
    d.name = records[r].name;
    for (const model::GroundMotionSection& c : records[r].components) d.files.push_back(c.file);
    if (!misfits.empty()) d.misfit = misfits[r];
    d.spectrum = sa;
    out.records.push_back(std::move(d));
  }
  out.display_periods = grid;
  for (const double t : grid)
    out.display_target.push_back(spectra::ContinuedSpectralAcceleration(design.target, t));
  out.target_fraction = eurocode ? kEurocode8SuiteFraction : 1.0;
  std::vector<double> target;
  for (const double t : periods) {
    target.push_back(out.target_fraction * spectra::SpectralAcceleration(design.target, t));
  }
  out.scaling = spectra::ScaleSuite(periods, target, in_range);
  if (eurocode) RaiseToPeakGroundAcceleration(design, records, suite, out);
  for (std::size_t r = 0; r < records.size(); ++r) {
    for (model::GroundMotionSection& c : records[r].components) c.scale *= out.scaling.factors[r];
    out.records[r].shape_factor = out.scaling.pair_shape_factors[r];
    out.records[r].factor = out.scaling.factors[r];
  }
  Tell(progress, SuiteLine(design, records.size(), directions, out));
  out.suite_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - suite_start).count();
  return records;
}

// 4. The study of every bound x eccentricity case x record x orientation. Each case's model is
// written as it runs, so that `isolab run` on the file reproduces its rows.
model::StudyFile DesignStudy(const model::DesignFile& design, const model::BoundModels& bounds,
                             const std::vector<model::StudyRecord>& records, const fs::path& models,
                             DesignOutcome& out) {
  out.eccentricities.push_back({"none", {}});
  if (design.eccentricity > 0.0) {
    for (const design::EccentricityCase& c :
         design::AccidentalEccentricities(design.model, design.eccentricity, "eccentricity")) {
      out.eccentricities.push_back(c);
    }
  }
  const int directions = model::Directions(design.model);
  model::StudyFile study;
  study.path = design.path;
  study.description = design.description;
  study.building_path = design.model_path;
  study.units = design.model.units;
  study.directions = directions;
  study.rotations = directions == 2;
  const std::string stem = fs::path(design.model_path).stem().string();
  for (std::size_t i = 0; i < out.bounds.size(); ++i) {
    DesignBound& b = out.bounds[i];
    for (const design::EccentricityCase& c : out.eccentricities) {
      model::StudyVariant variant;
      variant.name = c.name == "none" ? b.bound : b.bound + "_" + c.name;
      if (c.name == "none") {
        variant.model = b.model;
        b.case_model_files.push_back(b.model_file);
      } else {
        const std::string file =
            (models / (stem + "_" + b.bound + "_" + c.name + ".yaml")).string();
        const std::string text =
            model::WithCentresOfMassShiftedText(bounds.models[i].text, b.model, c.shift, c.name);
        io::WriteTextFileAtomically(file, [&](std::ostream& f) { f << text; });
        variant.model = model::LoadModelText(text, file);
        b.case_model_files.push_back(file);
      }
      study.variants.push_back(std::move(variant));
    }
  }
  out.orientations = design.orientations;
  for (const model::StudyRecord& record : records) {
    for (const double angle : out.orientations) {
      model::StudyRecord turned = record;
      turned.angle += angle;
      if (angle != 0.0) turned.name += fmt::format("_at{:g}", angle);
      study.records.push_back(std::move(turned));
    }
  }
  study.scales = {1.0};
  study.runs = model::RunFiles::kSummary;
  return study;
}

// 6. Histories for the figures: the record of the largest D_TM of the governing bound in the
// orientation that gave it, each bound in its worst eccentricity case for that record; run again
// with every history written, into <output>/histories.
void KeepFigureHistories(const std::string& output_directory, const std::string& version,
                         Scheduler& scheduler, DesignOutcome& out) {
  const std::size_t C = out.eccentricities.size(), O = out.orientations.size();
  const std::size_t total = static_cast<std::size_t>(DesignQuantity::kTotalDisplacement);
  const std::size_t g = out.governing[total];
  const std::vector<double>& governing = out.values[g][total].per_record;
  out.figure_record = static_cast<std::size_t>(
      std::max_element(governing.begin(), governing.end()) - governing.begin());
  const std::size_t q_total = static_cast<std::size_t>(Quantity::kIsolatorDisplacement);
  const auto peak = [&](std::size_t b, std::size_t c, std::size_t o) {
    return out.RunOf(b, c, out.figure_record, o).values[q_total];
  };
  double largest = -INFINITY;
  for (std::size_t c = 0; c < C; ++c) {
    for (std::size_t o = 0; o < O; ++o) {
      if (peak(g, c, o) > largest) {
        largest = peak(g, c, o);
        out.figure_orientation = o;
      }
    }
  }
  model::StudyFile histories = out.study;
  histories.variants.clear();
  histories.records = {out.study.records[out.figure_record * O + out.figure_orientation]};
  histories.runs = model::RunFiles::kFull;
  for (std::size_t b = 0; b < out.bounds.size(); ++b) {
    std::size_t worst = 0;
    for (std::size_t c = 1; c < C; ++c) {
      if (peak(b, c, out.figure_orientation) > peak(b, worst, out.figure_orientation)) worst = c;
    }
    model::StudyVariant variant = out.study.variants[b * C + worst];
    variant.name = out.bounds[b].bound;
    histories.variants.push_back(std::move(variant));
  }
  const std::vector<Job> history_jobs = ExpandJobs(histories);
  const fs::path history_folder = fs::path(output_directory) / "histories";
  fs::create_directories(history_folder);
  const ScheduleOutcome kept =
      RunStudy(histories, history_jobs, history_folder.string(), version, scheduler,
               [](const JobResult&, std::size_t, std::size_t) {});
  for (const JobResult& r : kept.results) {
    // The same runs completed above: a failure here is the disk's (full, or gone), and a design
    // without the histories its report names is not complete.
    if (!r.completed) {
      throw ResourceError(history_folder.string(),
                          fmt::format("the histories kept for the figures could not be written: "
                                      "{}",
                                      r.message));
    }
    out.history_files.push_back((fs::path("histories") / r.file).string());
  }
}

}  // namespace

DesignOutcome RunDesign(const model::DesignFile& design, const std::string& output_directory,
                        const std::string& version, Scheduler& scheduler,
                        const Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  DesignOutcome out;
  // 0. The given records, read and checked before any work.
  const std::vector<std::vector<io::Record>> given = ReadSuite(design.records, design.model);
  const fs::path models = fs::path(output_directory) / "models";
  const model::BoundModels bounds = ReadBoundModels(design, models, out);
  SolveBoundsByElf(design, out, progress);
  SetScalingRange(design, out);
  const std::vector<model::StudyRecord> records =
      ScaleSuiteToTarget(design, given, output_directory, out, progress);
  fs::create_directories(models);
  for (std::size_t i = 0; i < bounds.models.size(); ++i) {
    io::WriteTextFileAtomically(out.bounds[i].model_file,
                                [&](std::ostream& file) { file << bounds.models[i].text; });
    if (out.bounds[i].opensees_file.empty()) continue;
    io::WriteTextFileAtomically(out.bounds[i].opensees_file,
                                [&](std::ostream& file) { file << out.bounds[i].opensees_text; });
  }
  out.study = DesignStudy(design, bounds, records, models, out);
  const model::StudyFile& study = out.study;
  const std::vector<Job> jobs = ExpandJobs(study);
  Tell(progress,
       fmt::format("runs: {} bounds x {} eccentricity cases x {} records{} = {} runs on {}",
                   out.bounds.size(), out.eccentricities.size(), records.size(),
                   out.orientations.size() > 1
                       ? fmt::format(" x {} orientations ({} degrees)", out.orientations.size(),
                                     fmt::join(out.orientations, ", "))
                       : "",
                   jobs.size(), scheduler.Describe()));
  const ScheduleOutcome outcome =
      RunStudy(study, jobs, output_directory, version, scheduler,
               [&](const JobResult& result, std::size_t done, std::size_t total) {
                 Tell(progress, JobProgressLine(study, jobs[result.job], result, done, total));
               });
  out.runs = outcome.results;
  out.failed = outcome.failed;
  out.runs_seconds = outcome.wall_seconds;
  out.warnings = CollectWarnings(out);
  if (out.failed > 0) return out;
  // 5. Design values: per bound and record the envelope over the cases and orientations, then
  // over the suite.
  out.mean_of_suite = out.records.size() >= kMinimumRecordsForMean;
  HeadlineValues(out);
  out.parts = PartValues(out);
  KeepFigureHistories(output_directory, version, scheduler, out);
  out.checks = CheckDesign(design, out);
  out.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace isolab::study
