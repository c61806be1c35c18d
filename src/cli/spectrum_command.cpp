#include "spectrum_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common_options.h"
#include "isolab/core/errors.h"
#include "isolab/core/number.h"
#include "isolab/core/units.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/output_check.h"
#include "isolab/io/record.h"
#include "isolab/io/spectrum_file.h"
#include "isolab/spectra/constant_ductility.h"
#include "isolab/spectra/elastic_spectrum.h"
#include "isolab/spectra/period_list.h"
#include "isolab/spectra/spectrum_work.h"
#include "plot_script.h"

namespace isolab::cli {
namespace {

constexpr const char* kPlotScript = "plot_spectrum.py";

struct Inputs {
  std::vector<double> periods, damping, ductilities;
};

Inputs ParseInputs(const SpectrumOptions& options) {
  Inputs inputs;
  inputs.periods = spectra::ParsePeriods(options.periods, "--periods");
  inputs.damping = spectra::ParseNumberList(options.damping, "--damping");
  for (const double zeta : inputs.damping) {
    if (!(zeta >= 0.0 && zeta < 1.0)) {
      throw InputError(
          {"--damping"},
          fmt::format("damping ratio {:g} must be in [0, 1) (e.g. 0.05 for 5 %)", zeta));
    }
  }
  if (!options.ductility.empty()) {
    inputs.ductilities = spectra::ParseNumberList(options.ductility, "--ductility");
    for (const double mu : inputs.ductilities) {
      if (!(mu >= 1.0)) {
        throw InputError({"--ductility"}, fmt::format("ductility {:g} must be >= 1", mu));
      }
    }
  }
  if (!(options.alpha >= 0.0 && options.alpha < 1.0)) {
    throw InputError({"--alpha"}, fmt::format("{:g} must be in [0, 1)", options.alpha));
  }
  if (options.alpha != 0.0 && inputs.ductilities.empty()) {
    throw InputError({"--alpha"},
                     "the post-yield stiffness ratio of the constant-ductility spectra: give "
                     "--ductility");
  }
  if (options.points_per_period < 1) {
    throw InputError({"--points-per-period"},
                     fmt::format("{} must be >= 1", options.points_per_period));
  }
  if (!(options.max_steps >= 1.0)) {
    throw InputError({"--max-steps"}, fmt::format("{:g} must be >= 1", options.max_steps));
  }
  if (!(options.scale > 0.0) || !std::isfinite(options.scale)) {
    throw InputError({"--scale"}, fmt::format("{:g} must be finite and > 0", options.scale));
  }
  if (options.dt && !(*options.dt > 0.0 && std::isfinite(*options.dt))) {
    throw InputError({"--dt"}, fmt::format("{:g} must be finite and > 0", *options.dt));
  }
  for (const std::string& output : options.outputs) {
    if (!io::IsSpectrumFileName(output)) {
      throw InputError({"-o"}, fmt::format("'{}': the file type is known by its extension, "
                                           ".csv, .h5 or .hdf5",
                                           output));
    }
  }
  if (!options.record_h2.empty() && !inputs.ductilities.empty()) {
    throw InputError({"--ductility"},
                     "constant-ductility spectra of a pair do not follow from its components' "
                     "responses (an inelastic oscillator is not linear): give one record");
  }
  std::vector<std::string> inputs_read{options.record};
  if (!options.record_h2.empty()) inputs_read.push_back(options.record_h2);
  io::CheckOutputs(inputs_read, options.outputs);  // before a long scan, not after it
  if (options.plot && options.outputs.empty()) {
    throw InputError({"--plot"},
                     "needs an output file for the plot script to read (-o OUT.csv "
                     "or -o OUT.h5)");
  }
  return inputs;
}

nlohmann::json Numbers(const std::vector<double>& values) {
  nlohmann::json json = nlohmann::json::array();
  for (const double value : values) {
    if (std::isnan(value)) {
      json.push_back(nullptr);
    } else {
      json.push_back(value);
    }
  }
  return json;
}

// D, V, A and A in g of damping ratio d's curve.
nlohmann::json CurveJson(const spectra::ElasticSpectrum& e, std::size_t d, double gravity) {
  const std::size_t n = e.periods.size();
  std::vector<double> D(n), V(n), A(n), A_g(n);
  for (std::size_t p = 0; p < n; ++p) {
    D[p] = e.at(d, p).deformation;
    V[p] = e.at(d, p).pseudo_velocity;
    A[p] = e.at(d, p).pseudo_acceleration;
    A_g[p] = A[p] / gravity;
  }
  return {{"D", Numbers(D)}, {"V", Numbers(V)}, {"A", Numbers(A)}, {"A_g", Numbers(A_g)}};
}

nlohmann::json SpectrumJson(const io::SpectrumDescription& s, const std::vector<std::string>& files,
                            double seconds) {
  const spectra::ElasticSpectrum& e = s.pair != nullptr ? s.pair->h1 : *s.elastic;
  nlohmann::json json;
  json["record"] = s.record.path;
  json["scale"] = s.record.scale;
  json["record_units"] = s.record.units;
  json["pga_g"] = s.record.pga / s.gravity;
  json["units"] = {{"length", s.length_unit}, {"time", "s"}, {"g", s.gravity}};
  json["periods"] = e.periods;
  const std::size_t n = e.periods.size();
  if (s.pair != nullptr) {
    json["record_h2"] = s.record_h2.path;
    json["record_h2_units"] = s.record_h2.units;
    json["pga_h2_g"] = s.record_h2.pga / s.gravity;
    json["pair"] = nlohmann::json::array();
    for (std::size_t d = 0; d < e.damping_ratios.size(); ++d) {
      nlohmann::json curves = {{"damping", e.damping_ratios[d]}};
      for (const auto& [name, curve] : io::ElasticCurves(s)) {
        curves[name] = CurveJson(*curve, d, s.gravity);
      }
      curves["rotd100"]["angle"] = std::vector<double>(s.pair->rotd100_angle.begin() + d * n,
                                                       s.pair->rotd100_angle.begin() + (d + 1) * n);
      json["pair"].push_back(curves);
    }
  } else {
    json["elastic"] = nlohmann::json::array();
    for (std::size_t d = 0; d < e.damping_ratios.size(); ++d) {
      nlohmann::json curve = CurveJson(e, d, s.gravity);
      curve["damping"] = e.damping_ratios[d];
      json["elastic"].push_back(curve);
    }
  }
  if (s.constant_ductility != nullptr) {
    const spectra::ConstantDuctilitySpectrum& c = *s.constant_ductility;
    json["constant_ductility"] = nlohmann::json::array();
    for (std::size_t d = 0; d < c.damping_ratios.size(); ++d) {
      for (std::size_t m = 0; m < c.ductilities.size(); ++m) {
        std::vector<double> ratio(n), D_y(n), V_y(n), A_y(n), A_y_g(n), u_m(n), achieved(n);
        for (std::size_t p = 0; p < n; ++p) {
          const spectra::ConstantDuctilityPoint& x = c.at(d, m, p);
          ratio[p] = x.strength_ratio;
          D_y[p] = x.yield_deformation;
          V_y[p] = x.yield_pseudo_velocity;
          A_y[p] = x.yield_pseudo_acceleration;
          A_y_g[p] = A_y[p] / s.gravity;
          u_m[p] = x.peak_deformation;
          achieved[p] = x.achieved_ductility;
        }
        json["constant_ductility"].push_back({{"damping", c.damping_ratios[d]},
                                              {"ductility", c.ductilities[m]},
                                              {"alpha", c.alpha},
                                              {"strength_ratio", Numbers(ratio)},
                                              {"D_y", Numbers(D_y)},
                                              {"V_y", Numbers(V_y)},
                                              {"A_y", Numbers(A_y)},
                                              {"A_y_g", Numbers(A_y_g)},
                                              {"u_m", Numbers(u_m)},
                                              {"achieved_ductility", Numbers(achieved)}});
      }
    }
    json["newmark_runs"] = c.newmark_runs;
  }
  json["files"] = files;
  json["wall_seconds"] = seconds;
  return json;
}

// One table per damping ratio: the elastic D, V, A and, per target ductility, fy/fo and A_y.
void PrintTables(const io::SpectrumDescription& s, std::ostream& out) {
  const spectra::ElasticSpectrum& e = *s.elastic;
  const spectra::ConstantDuctilitySpectrum* c = s.constant_ductility;
  const std::string& L = s.length_unit;
  bool unreached = false;  // a target ductility no strength ratio scanned demands: "-"
  for (std::size_t d = 0; d < e.damping_ratios.size(); ++d) {
    fmt::print(out, "\nzeta = {:g}{}\n", e.damping_ratios[d],
               c != nullptr ? fmt::format(", constant ductility with alpha = {:g}", c->alpha) : "");
    fmt::print(out, "{:>8} {:>11} {:>11} {:>11} {:>8}", "T [s]", fmt::format("D [{}]", L),
               fmt::format("V [{}/s]", L), fmt::format("A [{}/s^2]", L), "A [g]");
    if (c != nullptr) {
      for (const double mu : c->ductilities) {
        fmt::print(out, " {:>9} {:>8}", fmt::format("fy/fo@{:g}", mu), fmt::format("Ay@{:g}", mu));
      }
    }
    fmt::print(out, "\n");
    for (std::size_t p = 0; p < e.periods.size(); ++p) {
      const spectra::SpectralOrdinate& o = e.at(d, p);
      fmt::print(out, "{:>8.4g} {:>11.5g} {:>11.5g} {:>11.5g} {:>8.4g}", e.periods[p],
                 o.deformation, o.pseudo_velocity, o.pseudo_acceleration,
                 o.pseudo_acceleration / s.gravity);
      if (c != nullptr) {
        for (std::size_t m = 0; m < c->ductilities.size(); ++m) {
          const spectra::ConstantDuctilityPoint& x = c->at(d, m, p);
          if (std::isnan(x.strength_ratio)) {
            unreached = true;
            fmt::print(out, " {:>9} {:>8}", "-", "-");
          } else {
            fmt::print(out, " {:>9.4g} {:>8.4g}", x.strength_ratio,
                       x.yield_pseudo_acceleration / s.gravity);
          }
        }
      }
      fmt::print(out, "\n");
    }
  }
  if (c != nullptr) {
    fmt::print(out,
               "\nfy/fo = f_y / (k u_o); Ay [g] = w^2 u_y / g; u_m in the files; Newmark: {} "
               "runs\n",
               c->newmark_runs);
    if (unreached) {
      fmt::print(out,
                 "-: no strength ratio fy/fo of {:g} or more demands that ductility at that "
                 "period (NaN in the files)\n",
                 spectra::ConstantDuctilityOptions{}.min_strength_ratio);
    }
  }
}

// A pair's table per damping ratio: each curve's A in g, and RotD100's direction.
void PrintPairTables(const io::SpectrumDescription& s, std::ostream& out) {
  const spectra::PairSpectrum& pair = *s.pair;
  const spectra::ElasticSpectrum& h1 = pair.h1;
  for (std::size_t d = 0; d < h1.damping_ratios.size(); ++d) {
    fmt::print(out, "\nzeta = {:g}: pseudo-acceleration A [g]\n", h1.damping_ratios[d]);
    fmt::print(out, "{:>8} {:>8} {:>8} {:>8} {:>8} {:>8} {:>10}\n", "T [s]", "H1", "H2", "geomean",
               "RotD50", "RotD100", "dir. [deg]");
    for (std::size_t p = 0; p < h1.periods.size(); ++p) {
      fmt::print(out, "{:>8.4g}", h1.periods[p]);
      for (const auto& [name, curve] : io::ElasticCurves(s)) {
        fmt::print(out, " {:>8.4g}", curve->at(d, p).pseudo_acceleration / s.gravity);
      }
      fmt::print(out, " {:>10.1f}\n", pair.rotd100_angle[d * h1.periods.size() + p]);
    }
  }
  fmt::print(out,
             "\nRotD50, RotD100: median and largest peak over the directions of the pair "
             "(Boore 2010); dir.: RotD100's, from H1 towards H2; D and V in the files\n");
}

// A record read, scaled and converted to the spectra's acceleration unit, and how it was applied.
struct Ground {
  io::Record record;
  integrators::SampledHistory acceleration;
  io::AppliedRecord applied;
};

Ground ReadGround(const SpectrumOptions& options, const std::string& path,
                  const UnitSystem& units) {
  Ground ground;
  ground.record = io::ReadRecord(path, {options.units, options.dt.value_or(0), "--units", "--dt"});
  const io::Record& record = ground.record;
  io::ScaledRecord scaled = io::ScaleRecord(record, options.scale, units, "--scale");
  ground.acceleration = {record.dt, std::move(scaled.values)};
  ground.applied = {path,      record.format, record.units, record.units_source,
                    record.dt, options.scale, scaled.pga};
  return ground;
}

}  // namespace

void RegisterSpectrumCommand(CLI::App& app, SpectrumOptions& options) {
  CLI::App* command = app.add_subcommand(
      "spectrum",
      "Elastic (exact piecewise-linear) and constant-ductility (Newmark, elastoplastic or "
      "bilinear) response spectra of a ground-motion record");
  command
      ->add_option("record", options.record,
                   "Ground-motion record (PEER AT2, Peknold AT2, CSV, columns)")
      ->required();
  command->add_option("record_h2", options.record_h2,
                      "Second horizontal component of the same motion (same step and length): "
                      "the pair's RotD50 and RotD100 spectra (Boore 2010) beside each "
                      "component's and their geometric mean");
  command->add_option("--damping", options.damping,
                      "Damping ratios, comma-separated, in [0, 1) (default 0.05)");
  command->add_option("--periods", options.periods,
                      "Periods in s: START:STOP:STEP or a comma-separated list "
                      "(default 0.05:5:0.05)");
  command->add_option("--ductility", options.ductility,
                      "Target ductilities >= 1, comma-separated: constant-ductility spectra");
  command->add_option("--alpha", options.alpha,
                      "Post-yield stiffness ratio of the inelastic system, [0, 1) (0: "
                      "elastoplastic)");
  command->add_option("--points-per-period", options.points_per_period,
                      "Elastic peaks sought at >= N points per period, the record's steps cut "
                      "into sub-steps (default 100; 1: at the record's samples, as Chopra)");
  command->add_option("--max-steps", options.max_steps,
                      "Refuse a spectrum of more SDOF steps than this, counted before it starts "
                      "(default 1e9: about 20 s of elastic spectra)");
  command->add_option("--scale", options.scale, "Scale factor on the record");
  command->add_option("--units", options.units,
                      "The record's acceleration unit (g, m/s^2, cm/s^2, in/s^2, ...); must "
                      "agree with its header when the header names one");
  command->add_option("--dt", options.dt,
                      "Sampling step of a single-column record (s); must agree with the file's "
                      "when it gives one");
  command->add_option("--length-unit", options.length_unit,
                      "Length unit of the spectra (m, cm, mm, in, ft; default m)");
  AddOutputOption(command, &options.outputs,
                  "Write the spectra: OUT.csv and/or OUT.h5 (repeat -o for both)");
  command->add_flag("--plot{}", options.plot,
                    "After writing, plot with plot_spectrum.py; --plot=DIR puts the PNGs in DIR "
                    "(default: beside the first output)");
  AddJsonFlag(command, &options.json, "Print the spectra as JSON");
  AddQuietFlag(command, &options.quiet);
}

void RunSpectrumCommand(const SpectrumOptions& options, std::ostream& out) {
  const auto start = std::chrono::steady_clock::now();
  const Inputs inputs = ParseInputs(options);
  double gravity = 0.0;
  std::optional<UnitSystem> units;
  try {
    units.emplace("N", options.length_unit, "s");
    gravity = units->Convert(1.0, "g", dimension::kAcceleration);
  } catch (const std::invalid_argument& error) {
    throw InputError({"--length-unit"}, fmt::format("'{}': {} (allowed: m, cm, mm, in, ft)",
                                                    options.length_unit, error.what()));
  }
  if (options.plot) CheckPlotScript(kPlotScript);

  const Ground h1 = ReadGround(options, options.record, *units);
  std::optional<Ground> h2;
  if (!options.record_h2.empty()) h2 = ReadGround(options, options.record_h2, *units);
  const integrators::SampledHistory& ground = h1.acceleration;
  try {
    if (h2) {
      spectra::ValidatePairInput(ground, h2->acceleration, inputs.periods, inputs.damping);
    } else {
      spectra::ValidateSpectrumInput(ground, inputs.periods, inputs.damping);
    }
  } catch (const InvalidParameter& error) {
    const bool about_h2 = error.violation().key.rfind("h2", 0) == 0;
    throw InputError({about_h2 ? options.record_h2 : options.record}, error.violation().Describe());
  }

  {
    spectra::ConstantDuctilityOptions inelastic;
    inelastic.alpha = options.alpha;
    spectra::CheckSpectrumWork(
        h2 ? spectra::PairSpectrumSteps(ground, inputs.periods, inputs.damping.size(),
                                        options.points_per_period)
           : spectra::SpectrumSteps(ground, inputs.periods, inputs.damping.size(),
                                    options.points_per_period, inputs.ductilities.size(),
                                    inelastic),
        options.max_steps, "--max-steps");
  }

  std::optional<spectra::PairSpectrum> pair;
  std::optional<spectra::ElasticSpectrum> elastic;
  if (h2) {
    pair = spectra::ComputePairSpectrum(ground, h2->acceleration, inputs.periods, inputs.damping,
                                        {options.points_per_period});
  } else {
    elastic = spectra::ComputeElasticSpectrum(ground, inputs.periods, inputs.damping,
                                              {options.points_per_period});
  }
  std::optional<spectra::ConstantDuctilitySpectrum> constant_ductility;
  if (!inputs.ductilities.empty()) {
    spectra::ConstantDuctilityOptions inelastic;
    inelastic.alpha = options.alpha;
    if (!options.quiet) {
      fmt::print(stderr,
                 "isolab spectrum: constant ductility {} for {} periods x {} damping ratios, "
                 "alpha = {:g}\n",
                 options.ductility, inputs.periods.size(), inputs.damping.size(), options.alpha);
      auto last = std::chrono::steady_clock::now();
      inelastic.progress = [last, start](const spectra::ConstantDuctilityProgress& p) mutable {
        const auto now = std::chrono::steady_clock::now();
        // At most one line a second: a progress line per period would flood a terminal.
        if (now - last < std::chrono::seconds(1) && p.done != p.total) return;
        last = now;
        fmt::print(stderr,
                   "  {:>5}/{} oscillators (T = {:g} s, zeta = {:g}), {} Newmark runs, "
                   "{:.1f} s\n",
                   p.done, p.total, p.period, p.damping_ratio, p.newmark_runs,
                   std::chrono::duration<double>(now - start).count());
      };
    }
    constant_ductility = spectra::ComputeConstantDuctilitySpectrum(
        ground, inputs.periods, inputs.damping, inputs.ductilities, inelastic);
  }

  io::SpectrumDescription description;
  description.elastic = elastic ? &*elastic : nullptr;
  description.pair = pair ? &*pair : nullptr;
  description.constant_ductility = constant_ductility ? &*constant_ductility : nullptr;
  description.record = h1.applied;
  if (h2) description.record_h2 = h2->applied;
  description.length_unit = options.length_unit;
  description.gravity = gravity;
  description.version = ISOLAB_VERSION;
  for (const std::string& output : options.outputs) io::WriteSpectrumFile(output, description);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  if (options.json) {
    out << SpectrumJson(description, options.outputs, seconds).dump(2) << "\n";
  } else {
    for (const Ground* g : std::initializer_list<const Ground*>{&h1, h2 ? &*h2 : nullptr}) {
      if (g == nullptr) continue;
      const io::Record& record = g->record;
      fmt::print(out,
                 "== {} ==\n{}: {} samples at {:g} s, in {} from {}; scale {:g}: PGA {:.4g} g\n",
                 g->applied.path, record.format, record.values.size(), record.dt, record.units,
                 record.units_source, options.scale, g->applied.pga / gravity);
    }
    if (pair) {
      PrintPairTables(description, out);
    } else {
      PrintTables(description, out);
    }
    for (const std::string& output : options.outputs) fmt::print(out, "spectra: {}\n", output);
    fmt::print(out, "{:.2f} s\n", seconds);
  }

  if (options.plot) {
    std::vector<std::string> arguments{options.outputs.front(), "-o",
                                       PlotDirectory(*options.plot, options.outputs.front())};
    if (options.quiet) arguments.push_back("--quiet");
    RunPlotScript(kPlotScript, arguments, options.quiet);
  }
}

}  // namespace isolab::cli
