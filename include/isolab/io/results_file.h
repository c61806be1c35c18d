// HDF5 results of a time-history run. Layout (n = output rows):
//   /time                                    (n)
//   /displacement /velocity /acceleration    (n x dofs), relative to the ground
//   /absolute_acceleration                   (n x dofs)
//   /connection_force                        (n x connections)
//   /isolator/displacement /isolator/force   (n), /isolator/component_force (n x components)
//   /story/drift /story/shear                (n x stories)
//   /energy/{input,kinetic,damping,elastic,hysteretic}  (n)
//   /model_yaml                              the model file's text (a string dataset)
// Every numeric dataset has a "units" attribute; the root's attributes give the record and its
// scale, the integrator options, the run summary and the isolab version. Story shear and base
// shear are the connections' (spring) forces; the superstructure's viscous forces are not in them.
// The file is written under a temporary name and renamed, so no partial file ever has the final
// name. A run that failed keeps its rows up to the failure, with termination = "failed" and the
// message.
#pragma once

#include <string>

#include "isolab/integrators/response.h"
#include "isolab/io/analysis_setup.h"
#include "isolab/io/model_file.h"

namespace isolab::io {

struct RunDescription {
  const ModelFile* model = nullptr;
  const AnalysisSetup* setup = nullptr;
  const AnalysisSection* analysis = nullptr;
  const integrators::ResponseHistory* response = nullptr;
  const integrators::RunSummary* summary = nullptr;
  std::string version;
};

// Throws InputError when the file cannot be written.
void WriteResultsFile(const std::string& path, const RunDescription& run);

}  // namespace isolab::io
