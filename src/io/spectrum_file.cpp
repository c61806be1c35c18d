#include "isolab/io/spectrum_file.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/hdf5_file.h"
#include "isolab/io/record_attributes.h"

namespace isolab::io {
namespace {

std::string Extension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

// Shortest text that reads back to the same double; "nan" for a strength not found.
std::string Number(double value) { return std::isnan(value) ? "nan" : fmt::format("{}", value); }

std::string DescribeRecord(const AppliedRecord& r, double gravity) {
  return fmt::format("{} (units {} from {}, scale {:g}, PGA {:.4g} g)", r.path, r.units,
                     r.units_source, r.scale, r.pga / gravity);
}

void WriteCsv(std::ostream& out, const SpectrumDescription& s) {
  const std::string& L = s.length_unit;
  fmt::print(
      out, "# isolab {} response spectra of {}{}; time in s, lengths in {}, 1 g = {:.6g} {}/s^2\n",
      s.version, DescribeRecord(s.record, s.gravity),
      s.pair != nullptr ? " and " + DescribeRecord(s.record_h2, s.gravity) : "", L, s.gravity, L);
  fmt::print(out,
             "curve,damping,ductility,alpha,period_s,D_{0},V_{0}/s,A_{0}/s^2,A_g,fy_over_fo,um_{0},"
             "achieved_ductility\n",
             L);
  for (const auto& [name, curve] : ElasticCurves(s)) {
    const spectra::ElasticSpectrum& e = *curve;
    for (std::size_t d = 0; d < e.damping_ratios.size(); ++d) {
      for (std::size_t p = 0; p < e.periods.size(); ++p) {
        const spectra::SpectralOrdinate& o = e.at(d, p);
        fmt::print(out, "{},{},,,{},{},{},{},{},,,\n", name, Number(e.damping_ratios[d]),
                   Number(e.periods[p]), Number(o.deformation), Number(o.pseudo_velocity),
                   Number(o.pseudo_acceleration), Number(o.pseudo_acceleration / s.gravity));
      }
    }
  }
  if (s.constant_ductility == nullptr) return;
  const spectra::ConstantDuctilitySpectrum& c = *s.constant_ductility;
  for (std::size_t d = 0; d < c.damping_ratios.size(); ++d) {
    for (std::size_t m = 0; m < c.ductilities.size(); ++m) {
      for (std::size_t p = 0; p < c.periods.size(); ++p) {
        const spectra::ConstantDuctilityPoint& x = c.at(d, m, p);
        fmt::print(out, "constant_ductility,{},{},{},{},{},{},{},{},{},{},{}\n",
                   Number(c.damping_ratios[d]), Number(c.ductilities[m]), Number(c.alpha),
                   Number(c.periods[p]), Number(x.yield_deformation),
                   Number(x.yield_pseudo_velocity), Number(x.yield_pseudo_acceleration),
                   Number(x.yield_pseudo_acceleration / s.gravity), Number(x.strength_ratio),
                   Number(x.peak_deformation), Number(x.achieved_ductility));
      }
    }
  }
}

void WriteHdf5(const std::string& path, const SpectrumDescription& s) {
  Hdf5File file(path);
  const std::vector<std::pair<std::string, const spectra::ElasticSpectrum*>> curves =
      ElasticCurves(s);
  const spectra::ElasticSpectrum& e = *curves.front().second;
  const std::string length = s.length_unit, velocity = length + "/s",
                    acceleration = length + "/s^2";
  const std::size_t nz = e.damping_ratios.size(), nt = e.periods.size();
  file.WriteDoubles("period", {nt}, e.periods, "s");
  file.WriteDoubles("damping", {nz}, e.damping_ratios, "1");
  for (const auto& [group, curve] : curves) {
    file.CreateGroup(group);
    std::vector<double> column(nz * nt);
    const auto write = [&](const char* name, double spectra::SpectralOrdinate::*field,
                           const std::string& units) {
      for (std::size_t k = 0; k < column.size(); ++k) column[k] = curve->ordinates[k].*field;
      file.WriteDoubles(fmt::format("{}/{}", group, name), {nz, nt}, column, units);
    };
    write("D", &spectra::SpectralOrdinate::deformation, length);
    write("V", &spectra::SpectralOrdinate::pseudo_velocity, velocity);
    write("A", &spectra::SpectralOrdinate::pseudo_acceleration, acceleration);
    write("time_of_peak", &spectra::SpectralOrdinate::time_of_peak, "s");
  }
  if (s.pair != nullptr) {
    file.WriteDoubles("rotd100/angle", {nz, nt}, s.pair->rotd100_angle, "degree");
    WriteRecordAttributes(file, s.record_h2, s.gravity, "record_h2");
  }
  if (s.constant_ductility != nullptr) {
    const spectra::ConstantDuctilitySpectrum& c = *s.constant_ductility;
    if (c.periods != e.periods || c.damping_ratios != e.damping_ratios) {
      throw std::logic_error("the elastic and constant-ductility spectra have different grids");
    }
    const std::size_t nm = c.ductilities.size();
    file.CreateGroup("constant_ductility");
    file.WriteAttribute("constant_ductility", "alpha", c.alpha);
    file.WriteDoubles("constant_ductility/ductility", {nm}, c.ductilities, "1");
    file.WriteDoubles("constant_ductility/time_step", {nt}, c.time_steps, "s");
    file.WriteDoubles("constant_ductility/elastic_deformation", {nz, nt}, c.elastic_deformations,
                      length);
    std::vector<double> column(c.points.size());
    const auto write = [&](const char* name, double spectra::ConstantDuctilityPoint::*field,
                           const std::string& units) {
      for (std::size_t k = 0; k < column.size(); ++k) column[k] = c.points[k].*field;
      file.WriteDoubles(fmt::format("constant_ductility/{}", name), {nz, nm, nt}, column, units);
    };
    write("strength_ratio", &spectra::ConstantDuctilityPoint::strength_ratio, "1");
    write("D_y", &spectra::ConstantDuctilityPoint::yield_deformation, length);
    write("V_y", &spectra::ConstantDuctilityPoint::yield_pseudo_velocity, velocity);
    write("A_y", &spectra::ConstantDuctilityPoint::yield_pseudo_acceleration, acceleration);
    write("u_m", &spectra::ConstantDuctilityPoint::peak_deformation, length);
    write("achieved_ductility", &spectra::ConstantDuctilityPoint::achieved_ductility, "1");
  }
  file.WriteAttribute("/", "isolab_version", s.version);
  WriteRecordAttributes(file, s.record, s.gravity);
  file.WriteAttribute("/", "units", fmt::format("length {}, time s", length));
  file.WriteAttribute("/", "gravity", s.gravity);
  file.WriteAttribute(
      "/", "method",
      "elastic: exact piecewise-linear recurrence (Nigam-Jennings; Chopra Sec. 5.2); constant "
      "ductility: Newmark average acceleration, largest strength giving the ductility (Chopra "
      "Sec. 7.5); a pair: RotD50 and RotD100 (Boore 2010) over 1-degree directions of the "
      "components' responses combined by linearity, RotD100 the largest in any direction");
  file.Commit();
}

}  // namespace

std::vector<std::pair<std::string, const spectra::ElasticSpectrum*>> ElasticCurves(
    const SpectrumDescription& s) {
  if (s.pair == nullptr) return {{"elastic", s.elastic}};
  const spectra::PairSpectrum& p = *s.pair;
  return {{"h1", &p.h1},
          {"h2", &p.h2},
          {"geometric_mean", &p.geometric_mean},
          {"rotd50", &p.rotd50},
          {"rotd100", &p.rotd100}};
}

bool IsSpectrumFileName(const std::string& path) {
  const std::string extension = Extension(path);
  return extension == ".csv" || extension == ".h5" || extension == ".hdf5";
}

void WriteSpectrumFile(const std::string& path, const SpectrumDescription& spectrum) {
  const std::string extension = Extension(path);
  if (extension == ".csv") {
    WriteTextFileAtomically(path, [&](std::ostream& out) { WriteCsv(out, spectrum); });
  } else if (extension == ".h5" || extension == ".hdf5") {
    WriteHdf5(path, spectrum);
  } else {
    throw InputError({path}, fmt::format("unknown spectrum file type '{}' (allowed: .csv, .h5, "
                                         ".hdf5)",
                                         extension));
  }
}

}  // namespace isolab::io
