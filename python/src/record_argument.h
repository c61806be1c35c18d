// A ground-motion record as Python gives it: a file's path, or a numpy array with its step and
// units.
#pragma once

#include <pybind11/numpy.h>

#include <optional>
#include <string>

#include "isolab/io/record.h"

namespace isolab::python {

// A str or an os.PathLike: a record file (else an array).
bool IsRecordFile(const pybind11::handle& record);

// The array's values at step `dt` (s) in `units`, named "<array>" in messages. Throws InputError
// naming record, record_dt or units when one is missing or wrong.
io::Record ArrayRecord(
    const pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>& values,
    std::optional<double> dt, const std::optional<std::string>& units);

}  // namespace isolab::python
