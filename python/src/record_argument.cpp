#include "record_argument.h"

#include <cmath>

#include "isolab/core/errors.h"

namespace py = pybind11;

namespace isolab::python {

bool IsRecordFile(const py::handle& record) {
  return py::isinstance<py::str>(record) || py::hasattr(record, "__fspath__");
}

io::Record ArrayRecord(const py::array_t<double, py::array::c_style | py::array::forcecast>& values,
                       std::optional<double> dt, const std::optional<std::string>& units) {
  if (values.ndim() != 1 || values.size() == 0) {
    throw InputError({"record"}, "an array record must be one-dimensional and not empty");
  }
  if (!dt || !(*dt > 0.0)) {
    throw InputError({"record_dt"}, "an array record needs its step: record_dt > 0 (s)");
  }
  if (!units || units->empty()) {
    throw InputError({"units"}, "an array record needs its units: units='g', 'm/s^2', ...");
  }
  io::Record record;
  record.path = "<array>";
  record.format = "array";
  record.units = *units;
  record.units_source = "units";
  record.dt = *dt;
  record.values.assign(values.data(), values.data() + values.size());
  for (const double value : record.values) {
    if (!std::isfinite(value)) throw InputError({"record"}, "the array has non-finite values");
  }
  return record;
}

}  // namespace isolab::python
