// `isolab synth`: writes a seeded synthetic ground motion (filtered white noise or a near-fault
// pulse) as a PEER AT2 file; see include/isolab/io/synthetic_motion.h.
#pragma once

#include <string>

#include "isolab/io/synthetic_motion.h"

namespace CLI {
class App;
}

namespace isolab::cli {

struct SynthOptions {
  std::string kind = "noise";  // noise | pulse
  std::string output;
  io::FilteredNoiseSpec noise;
  io::PulseSpec pulse;
};

void RegisterSynthCommand(CLI::App& app, SynthOptions& options);
void RunSynthCommand(const SynthOptions& options);

}  // namespace isolab::cli
