// isolab.spectrum: `isolab spectrum` (elastic and constant-ductility response spectra of a
// record, or a pair's RotD50/RotD100) with the command line's options as keyword arguments; the
// spectra as numpy arrays named as in the HDF5 spectrum file (io/spectrum_file.h).
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>

#include "bindings.h"
#include "isolab/core/errors.h"
#include "isolab/core/units.h"
#include "isolab/io/record.h"
#include "isolab/spectra/constant_ductility.h"
#include "isolab/spectra/elastic_spectrum.h"
#include "isolab/spectra/period_list.h"
#include "isolab/spectra/rotd_spectrum.h"
#include "isolab/spectra/spectrum_work.h"
#include "record_argument.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

// values[d * per_damping + i] as a (damping x per_damping) array, through `field`.
template <typename Item, typename Field>
py::array_t<double> Table(const std::vector<Item>& values, std::size_t rows, std::size_t columns,
                          Field field) {
  py::array_t<double> array({rows, columns});
  auto out = array.mutable_unchecked<2>();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns; ++c) out(r, c) = field(values[r * columns + c]);
  }
  return array;
}

// {"D", "V", "A", "A_g", "time_of_peak"} of an elastic curve, damping x period arrays; `g` in the
// spectra's length unit per s^2.
py::dict CurveDict(const spectra::ElasticSpectrum& e, double g) {
  const std::size_t nz = e.damping_ratios.size(), nt = e.periods.size();
  using spectra::SpectralOrdinate;
  return py::dict(
      py::arg("D") =
          Table(e.ordinates, nz, nt, [](const SpectralOrdinate& o) { return o.deformation; }),
      py::arg("V") =
          Table(e.ordinates, nz, nt, [](const SpectralOrdinate& o) { return o.pseudo_velocity; }),
      py::arg("A") = Table(e.ordinates, nz, nt,
                           [](const SpectralOrdinate& o) { return o.pseudo_acceleration; }),
      py::arg("A_g") = Table(e.ordinates, nz, nt,
                             [g](const SpectralOrdinate& o) { return o.pseudo_acceleration / g; }),
      py::arg("time_of_peak") =
          Table(e.ordinates, nz, nt, [](const SpectralOrdinate& o) { return o.time_of_peak; }));
}

// A record read (a file or an array), scaled into the spectra's unit, with its description.
struct Ground {
  integrators::SampledHistory acceleration;
  py::dict description;
};

Ground ReadGround(const py::object& record_argument, double scale,
                  const std::optional<std::string>& units, std::optional<double> record_dt,
                  const UnitSystem& system) {
  const io::Record record =
      IsRecordFile(record_argument)
          ? io::ReadRecord(py::str(record_argument).cast<std::string>(),
                           {units.value_or(""), record_dt.value_or(0.0), "units", "record_dt"})
          : ArrayRecord(record_argument, record_dt, units);
  io::ScaledRecord scaled = io::ScaleRecord(record, scale, system, "scale");
  Ground ground;
  ground.acceleration = {record.dt, std::move(scaled.values)};
  ground.description =
      py::dict(py::arg("path") = record.path, py::arg("format") = record.format,
               py::arg("units") = record.units, py::arg("dt") = record.dt, py::arg("scale") = scale,
               py::arg("pga") = scaled.pga);
  return ground;
}

// A pair's spectra (rotd_spectrum.h): each curve as "elastic" is, and RotD100's direction.
py::dict PairSpectrum(const Ground& h1, const Ground& h2, const std::vector<double>& periods,
                      const std::vector<double>& damping, int points_per_period, double max_steps,
                      double g, py::dict result) {
  try {
    spectra::ValidatePairInput(h1.acceleration, h2.acceleration, periods, damping);
  } catch (const InvalidParameter& error) {
    const bool about_h2 = error.violation().key.rfind("h2", 0) == 0;
    throw InputError({(about_h2 ? h2 : h1).description["path"].cast<std::string>()},
                     error.violation().Describe());
  }
  spectra::CheckSpectrumWork(
      spectra::PairSpectrumSteps(h1.acceleration, periods, damping.size(), points_per_period),
      max_steps, "max_steps");
  std::optional<spectra::PairSpectrum> pair;
  {
    py::gil_scoped_release release;
    pair = spectra::ComputePairSpectrum(h1.acceleration, h2.acceleration, periods, damping,
                                        {points_per_period});
  }
  result["record_h2"] = h2.description;
  result["h1"] = CurveDict(pair->h1, g);
  result["h2"] = CurveDict(pair->h2, g);
  result["geometric_mean"] = CurveDict(pair->geometric_mean, g);
  result["rotd50"] = CurveDict(pair->rotd50, g);
  py::dict rotd100 = CurveDict(pair->rotd100, g);
  rotd100["angle"] =
      Table(pair->rotd100_angle, damping.size(), periods.size(), [](double a) { return a; });
  result["rotd100"] = rotd100;
  return result;
}

py::dict Spectrum(const py::object& record_argument, const py::object& h2_argument,
                  const std::vector<double>& periods, const std::vector<double>& damping,
                  const std::vector<double>& ductility, double alpha, int points_per_period,
                  double scale, const std::optional<std::string>& units,
                  std::optional<double> record_dt, const std::string& length_unit,
                  double max_steps) {
  for (std::size_t k = 0; k < periods.size(); ++k) {
    if (!(periods[k] > 0.0 && periods[k] <= spectra::kMaxSpectrumPeriod)) {
      throw InputError({"periods"}, fmt::format("periods[{}] = {:g} must be > 0 and at most {:g} s",
                                                k, periods[k], spectra::kMaxSpectrumPeriod));
    }
  }
  for (const double zeta : damping) {
    if (!(zeta >= 0.0 && zeta < 1.0)) {
      throw InputError({"damping"}, "damping ratios must be in [0, 1) (e.g. 0.05 for 5 %)");
    }
  }
  for (const double mu : ductility) {
    if (!(mu >= 1.0) || !std::isfinite(mu)) {
      throw InputError({"ductility"}, "ductilities must be finite and >= 1");
    }
  }
  if (!(alpha >= 0.0 && alpha < 1.0)) throw InputError({"alpha"}, "must be in [0, 1)");
  if (alpha != 0.0 && ductility.empty()) {
    throw InputError({"alpha"},
                     "the post-yield stiffness ratio of the constant-ductility spectra: give "
                     "ductility");
  }
  if (points_per_period < 1) throw InputError({"points_per_period"}, "must be >= 1");
  if (!(max_steps >= 1.0) || !std::isfinite(max_steps)) {
    throw InputError({"max_steps"}, fmt::format("{:g} must be finite and >= 1", max_steps));
  }
  if (!(scale > 0.0) || !std::isfinite(scale)) {
    throw InputError({"scale"}, "must be finite and > 0");
  }
  std::optional<UnitSystem> system;
  try {
    system.emplace("N", length_unit, "s");
  } catch (const std::invalid_argument& error) {
    throw InputError({"length_unit"}, std::string(error.what()) + " (m, cm, mm, in, ft)");
  }
  const Ground h1 = ReadGround(record_argument, scale, units, record_dt, *system);
  py::dict result;
  result["period"] = py::array_t<double>(periods.size(), periods.data());
  result["damping"] = py::array_t<double>(damping.size(), damping.data());
  // Each array's unit, as the command line's table heads and CSV columns give them.
  const double g = system->Convert(1.0, "g", dimension::kAcceleration);
  const std::string L = length_unit;
  result["units"] = py::dict(
      py::arg("length") = L, py::arg("time") = "s", py::arg("g") = g, py::arg("period") = "s",
      py::arg("D") = L, py::arg("V") = L + "/s", py::arg("A") = L + "/s^2", py::arg("A_g") = "g",
      py::arg("time_of_peak") = "s", py::arg("angle") = "degrees", py::arg("D_y") = L,
      py::arg("V_y") = L + "/s", py::arg("A_y") = L + "/s^2", py::arg("A_y_g") = "g",
      py::arg("u_m") = L, py::arg("elastic_deformation") = L, py::arg("time_step") = "s");
  result["record"] = h1.description;
  if (!h2_argument.is_none()) {
    if (!ductility.empty()) {
      throw InputError({"ductility"},
                       "constant-ductility spectra of a pair do not follow from its components' "
                       "responses (an inelastic oscillator is not linear): give one record");
    }
    return PairSpectrum(h1, ReadGround(h2_argument, scale, units, record_dt, *system), periods,
                        damping, points_per_period, max_steps, g, result);
  }
  const integrators::SampledHistory& ground = h1.acceleration;
  try {
    spectra::ValidateSpectrumInput(ground, periods, damping);
  } catch (const InvalidParameter& error) {
    throw InputError({h1.description["path"].cast<std::string>()}, error.violation().Describe());
  }
  {
    spectra::ConstantDuctilityOptions inelastic;
    inelastic.alpha = alpha;
    spectra::CheckSpectrumWork(
        spectra::SpectrumSteps(ground, periods, damping.size(), points_per_period, ductility.size(),
                               inelastic),
        max_steps, "max_steps");
  }

  std::optional<spectra::ElasticSpectrum> elastic;
  std::optional<spectra::ConstantDuctilitySpectrum> inelastic;
  {
    py::gil_scoped_release release;
    elastic = spectra::ComputeElasticSpectrum(ground, periods, damping, {points_per_period});
    if (!ductility.empty()) {
      spectra::ConstantDuctilityOptions options;
      options.alpha = alpha;
      inelastic =
          spectra::ComputeConstantDuctilitySpectrum(ground, periods, damping, ductility, options);
    }
  }
  const std::size_t nz = damping.size(), nt = periods.size();
  result["elastic"] = CurveDict(*elastic, g);
  if (inelastic) {
    // (damping x ductility) rows of periods, reshaped to (n_z, n_mu, n_T) as in the HDF5 file.
    const std::size_t nm = ductility.size();
    using spectra::ConstantDuctilityPoint;
    const auto cube = [&](double (*field)(const ConstantDuctilityPoint&)) {
      return Table(inelastic->points, nz * nm, nt, field)
          .reshape(std::vector<py::ssize_t>{py::ssize_t(nz), py::ssize_t(nm), py::ssize_t(nt)});
    };
    result["constant_ductility"] = py::dict(
        py::arg("ductility") = py::array_t<double>(nm, ductility.data()), py::arg("alpha") = alpha,
        py::arg("time_step") = py::array_t<double>(nt, inelastic->time_steps.data()),
        py::arg("elastic_deformation") =
            Table(inelastic->elastic_deformations, nz, nt, [](double u) { return u; }),
        py::arg("strength_ratio") =
            cube([](const ConstantDuctilityPoint& p) { return p.strength_ratio; }),
        py::arg("D_y") = cube([](const ConstantDuctilityPoint& p) { return p.yield_deformation; }),
        py::arg("V_y") =
            cube([](const ConstantDuctilityPoint& p) { return p.yield_pseudo_velocity; }),
        py::arg("A_y") =
            cube([](const ConstantDuctilityPoint& p) { return p.yield_pseudo_acceleration; }),
        py::arg("A_y_g") =
            Table(inelastic->points, nz * nm, nt,
                  [g](const ConstantDuctilityPoint& p) { return p.yield_pseudo_acceleration / g; })
                .reshape(
                    std::vector<py::ssize_t>{py::ssize_t(nz), py::ssize_t(nm), py::ssize_t(nt)}),
        py::arg("u_m") = cube([](const ConstantDuctilityPoint& p) { return p.peak_deformation; }),
        py::arg("achieved_ductility") =
            cube([](const ConstantDuctilityPoint& p) { return p.achieved_ductility; }));
  }
  return result;
}

}  // namespace

void BindSpectrum(py::module_& module) {
  module.def("_parse_periods", &spectra::ParsePeriods, py::arg("text"), py::arg("option"));
  module.def("_parse_list", &spectra::ParseNumberList, py::arg("text"), py::arg("option"));
  module.def("_spectrum", &Spectrum, py::arg("record"), py::arg("h2"), py::arg("periods"),
             py::arg("damping"), py::arg("ductility"), py::arg("alpha"),
             py::arg("points_per_period"), py::arg("scale"), py::arg("units"), py::arg("record_dt"),
             py::arg("length_unit"), py::arg("max_steps"));
}

}  // namespace isolab::python
