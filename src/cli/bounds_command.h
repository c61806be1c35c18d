// `isolab bounds MODEL -o DIR`: the nominal, upper-bound and lower-bound models of a model with
// property modification factors (model/bounds.h), written as DIR/<model>_nominal.yaml,
// _upper.yaml and _lower.yaml, each a model `isolab run` runs alone, with the factors printed;
// with --opensees each bound's bearings also as OpenSees elements, DIR/<model>_<bound>.tcl
// (model/opensees_export.h).
#pragma once

#include <ostream>
#include <string>

namespace CLI {
class App;
}

namespace isolab::cli {

struct BoundsOptions {
  std::string model;
  std::string output;  // the folder the three models are written to (it must exist)
  bool opensees = false;  // also write each bound's bearings as an OpenSees model (.tcl)
  bool quiet = false;
};

void RegisterBoundsCommand(CLI::App& app, BoundsOptions& options);

// Throws InputError naming the file or option for bad input, before writing anything.
void RunBoundsCommand(const BoundsOptions& options, std::ostream& out);

}  // namespace isolab::cli
