// Model files (YAML). Sections read so far:
//
//   description: free text
//   units: {force: kN, length: mm, time: s}     # required; every number is in these units
//   isolation:
//     components:                               # a parallel assembly, one entry per law
//       - {name: c1, type: thm1, k0: 1.0, k1: 0.2, k2: 0.45, uy: 20, uyh: 120}
//       - {name: c2, type: thm2, ke: 1.0, kh1: 0.2, kh2: 0.05, fs: 16, uc: 120}
//   cyclic: {amplitude: 200, period: 1, cycles: 2, steps_per_cycle: 400}  # optional defaults
//
// A component gives its parameters in one form, mathematical or mechanical (law_parameters.h).
// Every error is an InputError "file:line:col: key path: what (what was allowed)".
#pragma once

#include <optional>
#include <string>

#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/hysteresis/parallel_assembly.h"

namespace isolab::io {

struct Units {
  std::string force = "kN";
  std::string length = "mm";
  std::string time = "s";
};

struct ModelFile {
  std::string path;
  std::string description;
  Units units;
  hysteresis::ParallelAssembly isolation;
  std::optional<hysteresis::CyclicProtocol> cyclic;
};

// Throws InputError for an unreadable file, bad YAML, unknown or missing keys, wrong types and
// parameters that break a law's rules.
ModelFile LoadModelFile(const std::string& path);

}  // namespace isolab::io
