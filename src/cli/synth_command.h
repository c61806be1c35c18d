// `isolab synth`: writes a seeded synthetic ground motion (filtered white noise or a near-fault
// pulse) as a PEER AT2 file; see include/isolab/analysis/synthetic_motion.h.
#pragma once

#include <string>

#include "isolab/analysis/synthetic_motion.h"

namespace CLI {
class App;
}

namespace isolab::cli {

struct SynthOptions {
  std::string kind = "noise";  // noise | pulse
  std::string output;
  analysis::FilteredNoiseSpec noise;
  analysis::PulseSpec pulse;
  bool quiet = false;  // -q: accepted as by every command; synth prints nothing but errors
};

void RegisterSynthCommand(CLI::App& app, SynthOptions& options);
void RunSynthCommand(const SynthOptions& options);

}  // namespace isolab::cli
