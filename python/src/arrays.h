// numpy arrays over isolab's own storage: views that keep their owner alive, read-only so that a
// result cannot be changed behind the summaries computed from it.
#pragma once

#include <pybind11/numpy.h>

#include <vector>

namespace isolab::python {

inline void MakeReadOnly(pybind11::array& array) {
  pybind11::detail::array_proxy(array.ptr())->flags &=
      ~pybind11::detail::npy_api::NPY_ARRAY_WRITEABLE_;
}

// `rows` doubles, or `rows` x `width` row-major when width > 0, at `data`, owned by `owner`.
inline pybind11::array View(const pybind11::object& owner, const double* data,
                            pybind11::ssize_t rows, pybind11::ssize_t width = 0) {
  constexpr pybind11::ssize_t size = sizeof(double);
  std::vector<pybind11::ssize_t> shape = {rows}, strides = {size};
  if (width > 0) {
    shape.push_back(width);
    strides = {width * size, size};
  }
  pybind11::array array = pybind11::array_t<double>(shape, strides, data, owner);
  MakeReadOnly(array);
  return array;
}

}  // namespace isolab::python
