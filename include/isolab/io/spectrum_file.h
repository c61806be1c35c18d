// Response spectra on disk, chosen by extension:
//  * .csv: one row per curve and period, long format, a '#' comment line with the record (units,
//    scale, PGA), then a header row naming each column with its unit:
//      curve,damping,ductility,alpha,period_s,D_<L>,V_<L>/s,A_<L>/s^2,A_g,fy_over_fo,um_<L>,
//      achieved_ductility
//    curve "elastic" (D, V, A the elastic ordinates; the last four fields empty) or
//    "constant_ductility" (D, V, A the yield values D_y, V_y, A_y of Chopra Sec. 7.5; fy_over_fo,
//    the peak deformation u_m and the demand achieved). "nan" marks a strength not found.
//  * .h5 / .hdf5 (n_z damping ratios, n_T periods, n_mu ductilities):
//      /period (n_T), /damping (n_z)
//      /elastic/{D,V,A,time_of_peak} (n_z x n_T)
//      /constant_ductility/ductility (n_mu), attribute alpha; /time_step (n_T);
//      /constant_ductility/elastic_deformation (n_z x n_T): u_o of the Newmark normalisation;
//      /constant_ductility/{strength_ratio,D_y,V_y,A_y,u_m,achieved_ductility} (n_z x n_mu x n_T)
//    every dataset with a "units" attribute; root attributes: record, record_units,
//    record_units_source, record_scale, record_pga (length/s^2), record_pga_g, units, gravity
//    (1 g in the file's acceleration unit), method, isolab_version.
// A pair's spectra (rotd_spectrum.h) take the elastic curve's place, five curves of the same
// columns: "h1", "h2" (the components as recorded), "geometric_mean", "rotd50", "rotd100"; in
// HDF5 the groups /h1, /h2, /geometric_mean, /rotd50, /rotd100, each {D,V,A,time_of_peak}
// (n_z x n_T; NaN where a curve has no time), and /rotd100/angle (n_z x n_T, degrees from H1
// towards H2), with the second component's attributes named record_h2, record_h2_units, ....
// Both are written atomically (atomic_file.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "isolab/io/record.h"
#include "isolab/spectra/constant_ductility.h"
#include "isolab/spectra/elastic_spectrum.h"
#include "isolab/spectra/rotd_spectrum.h"

namespace isolab::io {

struct SpectrumDescription {
  const spectra::ElasticSpectrum* elastic = nullptr;  // required unless `pair` is given
  const spectra::ConstantDuctilitySpectrum* constant_ductility = nullptr;  // may be null
  const spectra::PairSpectrum* pair = nullptr;  // a pair's spectra instead of `elastic`
  AppliedRecord record;                         // its pga in length_unit/s^2; H1 of a pair
  AppliedRecord record_h2;                      // a pair's H2
  std::string length_unit;                      // of every length in the spectra; time in s
  double gravity = 0.0;                         // 1 g in length_unit/s^2
  std::string version;
};

// The elastic curves of a description, named as the files name them: {"elastic"} of one record,
// or a pair's {"h1", "h2", "geometric_mean", "rotd50", "rotd100"}.
std::vector<std::pair<std::string, const spectra::ElasticSpectrum*>> ElasticCurves(
    const SpectrumDescription& spectrum);

// True for the extensions WriteSpectrumFile knows (.csv, .h5, .hdf5).
bool IsSpectrumFileName(const std::string& path);

// Throws InputError naming the file when it cannot be written or its extension is unknown.
void WriteSpectrumFile(const std::string& path, const SpectrumDescription& spectrum);

}  // namespace isolab::io
