#include "bindings.h"

PYBIND11_MODULE(_isolab, module) {
  module.doc() = "isolab: time-history analysis of base-isolated structures (the C++ library)";
  module.attr("__version__") = ISOLAB_VERSION;
  isolab::python::BindErrors(module);
  isolab::python::BindModel(module);
  isolab::python::BindRun(module);
  isolab::python::BindCyclic(module);
  isolab::python::BindSpectrum(module);
  isolab::python::BindFit(module);
  isolab::python::BindDiagnose(module);
  isolab::python::BindBuilding(module);
  isolab::python::BindCompare(module);
  isolab::python::BindDesign(module);
}
