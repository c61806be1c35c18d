// `isolab spectrum`: elastic and constant-ductility response spectra of a ground-motion record
// (spectra/elastic_spectrum.h, spectra/constant_ductility.h), or the elastic RotD50/RotD100
// spectra of a pair of records (spectra/rotd_spectrum.h), printed as a table or JSON and
// written as CSV and/or HDF5 (io/spectrum_file.h).
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "isolab/spectra/spectrum_work.h"

namespace CLI {
class App;
}

namespace isolab::cli {

struct SpectrumOptions {
  std::string record;
  std::string record_h2;                // a pair's second component: RotD50/RotD100 spectra
  std::string damping = "0.05";         // comma-separated ratios in [0, 1)
  std::string periods = "0.05:5:0.05";  // START:STOP:STEP (s, STOP included) or a list
  std::string ductility;                // comma-separated targets >= 1; empty: elastic only
  double alpha = 0.0;                   // post-yield stiffness ratio of the inelastic SDOF
  int points_per_period = 100;          // elastic peak sought at >= this many points a period
  double scale = 1.0;                   // on the record's values
  std::string units;                    // the record's acceleration unit (agrees with its header)
  std::optional<double> dt;             // sampling step of a single-column record (s)
  std::string length_unit = "m";        // of the spectra's lengths; time in s
  std::vector<std::string> outputs;     // .csv and/or .h5 files
  std::optional<std::string> plot;      // --plot[=DIR]: PNGs by plot_spectrum.py
  double max_steps = spectra::kDefaultMaxSpectrumSteps;  // refused above (spectrum_work.h)
  bool json = false;
  bool quiet = false;
};

void RegisterSpectrumCommand(CLI::App& app, SpectrumOptions& options);

// Throws InputError naming the file or option for bad input, before writing anything.
void RunSpectrumCommand(const SpectrumOptions& options, std::ostream& out);

}  // namespace isolab::cli
