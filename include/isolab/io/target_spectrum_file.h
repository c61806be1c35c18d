// A target spectrum given point by point (a site-specific MCE_R spectrum, a code spectrum
// exported from elsewhere), read from CSV for suite scaling (spectra/suite_scaling.h):
//   # any comment lines, blank lines anywhere
//   period_s,sa_g
//   0.01,0.45
//   0.2,1.1
//   ...
// Periods in s (>= 0, strictly increasing), pseudo-accelerations in g (>= 0), at least two
// points; Sa is linear between them and undefined outside (spectra/design_spectrum.h). The
// header names the units so that a table in other units (m/s^2, a frequency column) is refused
// instead of misread. Every error names the file and line and what was expected.
#pragma once

#include <string>

#include "isolab/spectra/design_spectrum.h"

namespace isolab::io {

// The table, with `source` the path. Throws InputError.
spectra::TabulatedSpectrum ReadTargetSpectrumCsv(const std::string& path);

}  // namespace isolab::io
