#include "synth_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <ostream>
#include <variant>

#include "common_options.h"
#include "heavy_commands.h"
#include "isolab/core/errors.h"
#include "isolab/design/matched_pairs.h"
#include "isolab/io/output_check.h"
#include "isolab/io/target_spectrum_file.h"
#include "isolab/spectra/design_spectrum.h"

namespace isolab::cli {
namespace {

// Ten million samples (1e5 s at the 0.01 s step): more is no earthquake record, and the samples
// are counted in an int. Ten samples at least: a record of one sample is all zero (its envelope
// starts at 0), and scaling it to the PGA divides by that zero.
constexpr double kMaxDuration = 1e5;
constexpr double kMaxSamples = 1e7;
constexpr int kMinSamples = 10;
// The step of PEER's records is 0.005 to 0.02 s; 0.001 to 0.05 s takes in every one of them.
constexpr double kMinDt = 0.001, kMaxDt = 0.05;
// Pairs: a suite of a thousand 10-minute records takes hours; more is a typing slip.
constexpr int kMaxPairs = 1000;
constexpr double kMaxPairDuration = 600.0;  // s
// Bounds no earthquake approaches, an order of magnitude past the largest recorded (PGA about 3 g,
// PGV about 3 m/s): what lies beyond is a unit slip, and near the largest doubles the samples
// overflow to infinity.
constexpr double kMaxPga = 10.0;     // g
constexpr double kMaxPgv = 30.0;     // m/s
constexpr double kMaxPeriod = 60.0;  // s
constexpr double kMaxOscillations = 100.0;

void Require(bool ok, const char* option, double value, const std::string& rule) {
  if (!ok) throw InputError({option}, fmt::format("{:g} ({})", value, rule));
}

// Every option of the kind asked for, before anything is generated: out of range, the filters or
// the scaling produce NaN samples (a zero duration, a zero pulse period) or no motion at all.
void CheckNoise(const analysis::FilteredNoiseSpec& s) {
  Require(s.pga > 0 && s.pga <= kMaxPga, "--pga", s.pga,
          fmt::format("must be > 0 and at most {:g} g", kMaxPga));
  Require(s.dt >= kMinDt && s.dt <= kMaxDt, "--dt", s.dt,
          fmt::format("must be at least {:g} s and at most {:g} s", kMinDt, kMaxDt));
  const double longest = std::min(kMaxDuration, kMaxSamples * s.dt);
  Require(s.duration >= kMinSamples * s.dt && s.duration <= longest, "--duration", s.duration,
          fmt::format("must be at least {:g} s ({} samples) and at most {:g} s", kMinSamples * s.dt,
                      kMinSamples, longest));
  // RK4 integrates the site filter at dt: a quarter of the sampling rate keeps w dt < 1.6.
  const double highest = 0.25 / s.dt;
  Require(s.site_frequency > 0 && s.site_frequency <= highest, "--site-frequency", s.site_frequency,
          fmt::format("must be > 0 and at most {:g} Hz", highest));
  Require(s.site_damping > 0 && s.site_damping <= 1, "--site-damping", s.site_damping,
          "must be in (0, 1]");
  Require(s.strong_end >= s.rise_end, "--strong-end", s.strong_end,
          fmt::format("must be >= the envelope's rise time, {:g} s", s.rise_end));
}

void CheckPulse(const analysis::PulseSpec& s) {
  Require(s.period >= 10 * s.dt && s.period <= kMaxPeriod, "--pulse-period", s.period,
          fmt::format("must be >= {:g} s, ten samples, and at most {:g} s", 10 * s.dt, kMaxPeriod));
  Require(s.pgv > 0 && s.pgv <= kMaxPgv, "--pgv", s.pgv,
          fmt::format("must be > 0 and at most {:g} m/s", kMaxPgv));
  Require(s.oscillations > 1 && s.oscillations <= kMaxOscillations, "--oscillations",
          s.oscillations, fmt::format("must be > 1 and at most {:g}", kMaxOscillations));
}

// The noise's spec with --duration and --dt where given.
analysis::FilteredNoiseSpec NoiseShape(const SynthOptions& o) {
  analysis::FilteredNoiseSpec noise = o.noise;
  if (o.duration) noise.duration = *o.duration;
  if (o.dt) noise.dt = *o.dt;
  return noise;
}

// The option a field of MatchedPairSpec comes from, for its violations.
const char* OptionOf(const std::string& key) {
  if (key == "count") return "--pairs";
  if (key == "period_min" || key == "period_max") return "--periods";
  if (key == "tolerance") return "--tolerance";
  if (key == "motion.dt") return "--dt";
  if (key == "motion.duration") return "--duration";
  return "--target";
}

int RunPairs(const SynthOptions& o, std::ostream& out) {
  // Options of the other modes are refused, not ignored.
  if (o.kind == "pulse") {
    throw InputError({"--pairs"}, "matches pairs of filtered noise: not with pulse");
  }
  if (o.pga) {
    throw InputError({"--pga"}, "the pairs are scaled to --target: give no --pga with --pairs");
  }
  const int count = *o.pairs;
  Require(count >= 1 && count <= kMaxPairs, "--pairs", count,
          fmt::format("must be at least 1 and at most {}", kMaxPairs));
  const analysis::FilteredNoiseSpec shape = NoiseShape(o);
  CheckNoise(shape);
  Require(shape.duration <= kMaxPairDuration, "--duration", shape.duration,
          fmt::format("must be at most {:g} s with --pairs", kMaxPairDuration));
  if (o.target.empty()) throw InputError({"--pairs"}, "needs --target: the spectrum to match");
  design::MatchedPairSpec spec;
  spec.seed = o.noise.seed;
  spec.count = count;
  spec.motion = shape;
  if (!o.periods.empty()) {
    if (o.periods.size() != 2) {
      throw InputError({"--periods"},
                       fmt::format("{} value(s): give LO,HI in s", o.periods.size()));
    }
    spec.period_min = o.periods[0];
    spec.period_max = o.periods[1];
  }
  if (o.tolerance) spec.tolerance = *o.tolerance;
  spec.target_name = std::filesystem::path(o.target).filename().string();
  try {
    spec.Validate();
  } catch (const InvalidParameter& error) {
    const ParameterViolation& v = error.violation();
    throw InputError({OptionOf(v.key)}, fmt::format("{:g} ({})", v.value, v.rule));
  }

  // Every output checked before the table is read and the work starts.
  if (!std::filesystem::is_directory(o.output)) {
    throw InputError({"--output"}, fmt::format("'{}' is not a folder", o.output));
  }
  const int width = static_cast<int>(std::to_string(count).size());
  std::vector<std::string> paths;
  for (int k = 1; k <= count; ++k) {
    for (const char* component : {"h1", "h2"}) {
      paths.push_back(
          (std::filesystem::path(o.output) / fmt::format("pair{:0{}}_{}.at2", k, width, component))
              .string());
    }
  }
  io::CheckOutputs({o.target}, paths);
  const spectra::TargetSpectrum target = io::ReadTargetSpectrumCsv(o.target);
  const spectra::TabulatedSpectrum& table = std::get<spectra::TabulatedSpectrum>(target);
  if (spec.period_min < table.periods.front() || spec.period_max > table.periods.back()) {
    throw InputError(
        {"--periods"},
        fmt::format("{:g},{:g} s is not inside the periods of {}, [{:g}, {:g}] s", spec.period_min,
                    spec.period_max, o.target, table.periods.front(), table.periods.back()));
  }

  const std::vector<design::MatchedPair> pairs = design::MatchPairs(
      spec, [&target](double period) { return spectra::SpectralAcceleration(target, period); });
  std::vector<std::string> failed;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    analysis::WriteAt2(pairs[k].h1, paths[2 * k]);
    analysis::WriteAt2(pairs[k].h2, paths[2 * k + 1]);
    fmt::print(out, "pair {:0{}}: misfit {:.4f} after {} iterations{}  {} {}\n", k + 1, width,
               pairs[k].misfit, pairs[k].iterations, pairs[k].converged ? "" : " (NOT CONVERGED)",
               paths[2 * k], paths[2 * k + 1]);
    if (!pairs[k].converged) failed.push_back(fmt::format("{:0{}}", k + 1, width));
  }
  if (failed.empty()) return 0;
  std::cerr << fmt::format(
      "isolab: synth: pair {} did not converge: RotD100 not within --tolerance {:g} of the "
      "target over [{:g}, {:g}] s after {} iterations (records written all the same)\n",
      fmt::join(failed, ", "), spec.tolerance, spec.period_min, spec.period_max,
      spec.max_iterations);
  return 1;
}

}  // namespace

void RegisterSynthCommand(CLI::App& app, SynthOptions& o) {
  CLI::App* command =
      app.add_subcommand(std::string(kSynthCommand.name), std::string(kSynthCommand.help));
  command->add_option("kind", o.kind, "noise (filtered white noise) or pulse (near-fault)")
      ->check(CLI::IsMember({"noise", "pulse"}));
  AddOutputOption(command, &o.output, "AT2 file to write; with --pairs, the folder")->required();
  o.noise_only.push_back(AddSeedOption(command, &o.noise.seed, "noise, pairs: random seed"));
  command->add_option("--pga", o.pga, "noise: peak ground acceleration (g), (0, 10]");
  command->add_option("--duration", o.duration, "noise, pairs: duration (s), ten samples or more");
  command->add_option("--dt", o.dt, "noise, pairs: time step (s), [0.001, 0.05]");
  command->add_option("--pairs", o.pairs,
                      "Write N pairs of filtered noise (pair<k>_h1.at2, pair<k>_h2.at2 in the "
                      "--output folder) whose RotD100 matches --target");
  command->add_option("--target", o.target,
                      "pairs: target spectrum, CSV with the header period_s,sa_g (s, g)");
  command->add_option("--periods", o.periods, "pairs: LO,HI (s), the range to match; 0.1,5")
      ->delimiter(',');
  command->add_option("--tolerance", o.tolerance,
                      "pairs: largest |RotD100/target - 1| accepted over --periods; 0.1");
  o.noise_only = {
      o.noise_only[0],
      command->add_option("--site-frequency", o.noise.site_frequency,
                          "noise: Kanai-Tajimi fg (Hz), up to a quarter of the sampling rate"),
      command->add_option("--site-damping", o.noise.site_damping, "noise: Kanai-Tajimi zg, (0, 1]"),
      command->add_option("--strong-end", o.noise.strong_end,
                          "noise: end of the strong phase t2 (s), >= the 2 s rise")};
  o.pulse_only = {
      command->add_option("--pulse-period", o.pulse.period,
                          "pulse: Tp (s), ten samples or more, at most 60 s"),
      command->add_option("--pgv", o.pulse.pgv, "pulse: peak ground velocity (m/s), (0, 30]"),
      command->add_option("--oscillations", o.pulse.oscillations, "pulse: gamma, (1, 100]"),
      command->add_option("--phase", o.pulse.phase, "pulse: nu (rad)")};
  AddQuietFlag(command, &o.quiet,
               "Accepted by every command (synth prints nothing but the pairs' misfits)");
}

int RunSynthCommand(const SynthOptions& o, std::ostream& out) {
  // Options of the other kind are refused, not ignored.
  const bool pulse = o.kind == "pulse" && !o.pairs;
  for (const CLI::Option* option : pulse ? o.noise_only : o.pulse_only) {
    if (option->count() > 0) {
      throw InputError({option->get_name()},
                       pulse ? "shapes noise (and pairs): not a pulse"
                             : "shapes a pulse: give kind pulse (not with --pairs)");
    }
  }
  if (pulse && o.pga) {
    throw InputError({"--pga"}, "scales noise: a pulse is given by its --pgv");
  }
  if (o.pairs) return RunPairs(o, out);
  const char* pairs_only = "matches pairs to a target spectrum: give --pairs";
  if (!o.target.empty()) throw InputError({"--target"}, pairs_only);
  if (!o.periods.empty()) throw InputError({"--periods"}, pairs_only);
  if (o.tolerance) throw InputError({"--tolerance"}, pairs_only);
  if (o.kind == "pulse") {
    // The pulse's record is 12 s at 0.01 s (synthetic_motion.h): not the noise's options.
    if (o.duration) throw InputError({"--duration"}, "sets noise's length: not a pulse's");
    if (o.dt) throw InputError({"--dt"}, "sets noise's step: not a pulse's");
    CheckPulse(o.pulse);
    analysis::WriteAt2(analysis::PulseRecord(o.pulse), o.output);
  } else {
    analysis::FilteredNoiseSpec noise = NoiseShape(o);
    if (o.pga) noise.pga = *o.pga;
    CheckNoise(noise);
    analysis::WriteAt2(analysis::FilteredNoiseRecord(noise), o.output);
  }
  return 0;
}

}  // namespace isolab::cli
