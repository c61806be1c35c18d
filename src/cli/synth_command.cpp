#include "synth_command.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "isolab/core/errors.h"

namespace isolab::cli {
namespace {

// Ten million samples (1e5 s at the 0.01 s step): more is no earthquake record, and the samples
// are counted in an int. Ten samples at least: a record of one sample is all zero (its envelope
// starts at 0), and scaling it to the PGA divides by that zero.
constexpr double kMaxDuration = 1e5;
constexpr int kMinSamples = 10;
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
  Require(s.duration >= kMinSamples * s.dt && s.duration <= kMaxDuration, "--duration", s.duration,
          fmt::format("must be at least {:g} s ({} samples) and at most {:g} s", kMinSamples * s.dt,
                      kMinSamples, kMaxDuration));
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

}  // namespace

void RegisterSynthCommand(CLI::App& app, SynthOptions& o) {
  CLI::App* command = app.add_subcommand("synth", "Write a seeded synthetic ground motion (AT2)");
  command->add_option("kind", o.kind, "noise (filtered white noise) or pulse (near-fault)")
      ->check(CLI::IsMember({"noise", "pulse"}));
  command->add_option("-o,--output", o.output, "AT2 file to write")->required();
  command->add_option("--seed", o.noise.seed, "noise: random seed");
  command->add_option("--pga", o.noise.pga, "noise: peak ground acceleration (g), (0, 10]");
  command->add_option("--duration", o.noise.duration, "noise: duration (s), ten samples or more");
  command->add_option("--site-frequency", o.noise.site_frequency,
                      "noise: Kanai-Tajimi fg (Hz), up to a quarter of the sampling rate");
  command->add_option("--site-damping", o.noise.site_damping, "noise: Kanai-Tajimi zg, (0, 1]");
  command->add_option("--strong-end", o.noise.strong_end,
                      "noise: end of the strong phase t2 (s), >= the 2 s rise");
  command->add_option("--pulse-period", o.pulse.period,
                      "pulse: Tp (s), ten samples or more, at most 60 s");
  command->add_option("--pgv", o.pulse.pgv, "pulse: peak ground velocity (m/s), (0, 30]");
  command->add_option("--oscillations", o.pulse.oscillations, "pulse: gamma, (1, 100]");
  command->add_option("--phase", o.pulse.phase, "pulse: nu (rad)");
  command->add_flag("-q,--quiet", o.quiet, "Accepted by every command (synth prints nothing)");
}

void RunSynthCommand(const SynthOptions& o) {
  if (o.kind == "pulse") {
    CheckPulse(o.pulse);
    analysis::WriteAt2(analysis::PulseRecord(o.pulse), o.output);
  } else {
    CheckNoise(o.noise);
    analysis::WriteAt2(analysis::FilteredNoiseRecord(o.noise), o.output);
  }
}

}  // namespace isolab::cli
