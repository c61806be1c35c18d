#include "synth_command.h"

#include <CLI/CLI.hpp>

namespace isolab::cli {

void RegisterSynthCommand(CLI::App& app, SynthOptions& o) {
  CLI::App* command = app.add_subcommand("synth", "Write a seeded synthetic ground motion (AT2)");
  command->add_option("kind", o.kind, "noise (filtered white noise) or pulse (near-fault)")
      ->check(CLI::IsMember({"noise", "pulse"}));
  command->add_option("-o,--output", o.output, "AT2 file to write")->required();
  command->add_option("--seed", o.noise.seed, "noise: random seed");
  command->add_option("--pga", o.noise.pga, "noise: peak ground acceleration (g)");
  command->add_option("--duration", o.noise.duration, "noise: duration (s)");
  command->add_option("--site-frequency", o.noise.site_frequency, "noise: Kanai-Tajimi fg (Hz)");
  command->add_option("--site-damping", o.noise.site_damping, "noise: Kanai-Tajimi zg");
  command->add_option("--strong-end", o.noise.strong_end, "noise: end of the strong phase t2 (s)");
  command->add_option("--pulse-period", o.pulse.period, "pulse: Tp (s)");
  command->add_option("--pgv", o.pulse.pgv, "pulse: peak ground velocity (m/s)");
  command->add_option("--oscillations", o.pulse.oscillations, "pulse: gamma (> 1)");
  command->add_option("--phase", o.pulse.phase, "pulse: nu (rad)");
}

void RunSynthCommand(const SynthOptions& o) {
  io::WriteAt2(o.kind == "pulse" ? io::PulseRecord(o.pulse) : io::FilteredNoiseRecord(o.noise),
               o.output);
}

}  // namespace isolab::cli
