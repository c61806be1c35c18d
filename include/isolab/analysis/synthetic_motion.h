// Ground motions isolab makes itself, documented and seeded, so examples run without external
// data (ground_motions/README.md lists the commands that made the bundled ones).
//
//  * Filtered white noise: Gaussian white noise through the Kanai-Tajimi site filter (frequency
//    wg, damping zg) and the Clough-Penzien high-pass (wf, zf), times the Jennings et al. (1968)
//    envelope (t/t1)^2, 1, exp(-c (t - t2)), scaled to a target peak ground acceleration. The
//    noise is Box-Muller on std::mt19937_64, whose output the C++ standard fixes, so a seed gives
//    the same record on every platform.
//  * Near-fault pulse: Mavroeidis & Papageorgiou (2003) velocity pulse
//      v(t) = A/2 [1 + cos(2 pi fp (t - t0) / gamma)] cos(2 pi fp (t - t0) + nu),
//    |t - t0| <= gamma / (2 fp), differentiated exactly for the acceleration.
#pragma once

#include <cstdint>
#include <string>

#include "isolab/io/record.h"

namespace isolab::analysis {

struct FilteredNoiseSpec {
  std::uint64_t seed = 1;
  double duration = 30.0;       // s
  double dt = 0.01;             // s
  double pga = 0.3;             // g
  double site_frequency = 2.5;  // Hz (Kanai-Tajimi wg / 2 pi)
  double site_damping = 0.6;
  double high_pass_frequency = 0.25;  // Hz (Clough-Penzien wf / 2 pi)
  double high_pass_damping = 0.6;
  double rise_end = 2.0;     // t1, s
  double strong_end = 12.0;  // t2, s
  double decay = 0.25;       // c, 1/s
};

struct PulseSpec {
  double period = 2.0;        // Tp = 1 / fp, s
  double pgv = 0.8;           // A, m/s
  double oscillations = 2.0;  // gamma > 1
  double phase = 0.0;         // nu, rad
  double peak_time = 4.0;     // t0, s
  double duration = 12.0;     // s
  double dt = 0.01;           // s
};

// Records in g at the spec's dt; description says how they were made.
io::Record FilteredNoiseRecord(const FilteredNoiseSpec& spec);
io::Record PulseRecord(const PulseSpec& spec);

// Writes a record in PEER AT2 layout (NGA-West2 header, values in g, five per line), atomically.
// Throws std::invalid_argument, writing nothing, for fewer than two samples or a non-finite one.
void WriteAt2(const io::Record& record, const std::string& path);

}  // namespace isolab::analysis
