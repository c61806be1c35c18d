// The extension module isolab._isolab, one registration function per area; module.cpp calls them
// in order. The pure-Python package (python/isolab) wraps it.
#pragma once

#include <pybind11/pybind11.h>

namespace isolab::python {

// isolab.InputError (a ValueError) and isolab.RunError (a RuntimeError).
void BindErrors(pybind11::module_& module);
// Model, load_model, model_from_dict.
void BindModel(pybind11::module_& module);
// run and its Result.
void BindRun(pybind11::module_& module);
// cyclic and its CyclicResult.
void BindCyclic(pybind11::module_& module);
// spectrum.
void BindSpectrum(pybind11::module_& module);
// fit.
void BindFit(pybind11::module_& module);
// diagnose.
void BindDiagnose(pybind11::module_& module);
// fit and diagnose of a building (building=).
void BindBuilding(pybind11::module_& module);
// compare.
void BindCompare(pybind11::module_& module);
// design.
void BindDesign(pybind11::module_& module);

}  // namespace isolab::python
