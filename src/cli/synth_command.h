// `isolab synth`: writes a seeded synthetic ground motion (filtered white noise or a near-fault
// pulse) as a PEER AT2 file (include/isolab/analysis/synthetic_motion.h); or, with --pairs, a
// suite of horizontal pairs whose RotD100 matches a target spectrum given as a table
// (include/isolab/design/matched_pairs.h), written into a folder.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "isolab/analysis/synthetic_motion.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace isolab::cli {

struct SynthOptions {
  std::string kind = "noise";  // noise | pulse
  std::string output;          // the AT2 file; with --pairs, the folder
  analysis::FilteredNoiseSpec noise;
  std::optional<double> pga;           // --pga, into noise.pga; refused with --pairs
  std::optional<double> duration, dt;  // --duration, --dt: of noise and pairs; refused for a pulse
  analysis::PulseSpec pulse;
  // Spectrum-compatible pairs: --pairs N matched to the table --target over --periods LO,HI.
  std::optional<int> pairs;  // none: a single record
  std::string target;
  std::vector<double> periods;      // LO,HI (s); empty: 0.1,5
  std::optional<double> tolerance;  // largest |RotD100/target - 1|; default 0.1
  bool quiet = false;  // -q: accepted as by every command; synth prints nothing but errors and
                       // the pairs' misfits
  // The options that shape only noise (and pairs) and only a pulse, to refuse those of the other
  // kind: their values have defaults, so whether one was given is asked of the parser.
  std::vector<const CLI::Option*> noise_only, pulse_only;
};

void RegisterSynthCommand(CLI::App& app, SynthOptions& options);
// The exit code: 0, or 1 when a pair's RotD100 is not within the tolerance of the target (its
// records are written all the same, their description says so). Throws InputError for bad
// options, before writing anything.
int RunSynthCommand(const SynthOptions& options, std::ostream& out);

}  // namespace isolab::cli
