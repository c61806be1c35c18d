// Results of a time-history run, in the format the file's extension names, the same for every
// structure (layout.h; "x"/"y" suffixes only where a quantity has two horizontal components):
//
// .h5 / .hdf5 (docs/results.md has every dataset with its shape, units and meaning; n = output
// rows; every numeric dataset has a "units" attribute, every 2-D one a "columns" attribute
// naming its columns; a single column is written as a vector; the histories are those the output
// selection records, output_selection.h, with only the selected levels' columns):
//   /time (n), /ground_acceleration (n, or n x 2 in plan: x, y; with a record)
//   /displacement /velocity /acceleration /absolute_acceleration (n x translations), relative to
//     the ground; columns "base", "floor 1", ... (an SDOF: "mass"), in plan "base.x", "base.y", ...
//   /rotation (n x levels, rad): the levels' rotations, in plan
//   /connection_force (n x force columns): "isolation" (or each isolator's .x and .y), the
//     stories' members (torsion members' torques are /story/torque)
//   /isolator/displacement /isolator/force (n, or n x isolators and directions),
//     /isolator/resultant (in plan), /isolator/component_force (n x components and directions)
//   /story/drift /story/drift_ratio (%) /story/shear (n x stories and directions),
//     /story/twist (rad) /story/torque (in plan), /story/height (stories)
//   /energy/{input,kinetic,damping,elastic,hysteretic} (n)
//   /model_summary/...: total mass and weight, fixed-base periods, isolated periods at the
//     trial displacement, the record's PGA (model_summary.h)
//   /peaks/<name>: each peak of response_peaks.h (scalar, "units", attributes "time" and,
//     where it has one, "index"), /peaks/isolators: each isolator's, /final_energy/<term>: the
//     energies at the end (scalars)
//   /model_yaml: the model file's text
//   attributes of /: the record (path, format, units and where they came from, step, scale,
//     PGA; a pair's second component as record_h2_*, with incidence_angle), the units, the
//     integrator and its counts (integers), termination and message, the energy balance error,
//     the excitation's end, the free vibration, the residual isolator displacement, warnings, the
//     isolab version; the selection: output_every (analysis steps between rows),
//     output_quantities, output_levels (the levels' names), summary_only (0 or 1).
// .csv: the same time histories as columns named "<series>[/<column>] [<units>]", e.g.
//   "time [s]", "displacement/floor 1 [mm]", "isolator/component_force/c1 [kN]", after '#'
//   comment lines with the model, the record (units, scale, PGA), the selection, the peaks, the
//   summary and the warnings (pandas: read_csv(path, comment="#")); summary-only: the comment
//   lines alone.
//
// Story shear and base shear are the members' (spring) forces; the superstructure's viscous
// forces are not in them. A run that failed keeps its rows up to the failure, with termination
// "failed" and the message. Files are written atomically (atomic_file.h); results_writer.h
// streams them while the run advances.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/response_peaks.h"
#include "isolab/integrators/response.h"
#include "isolab/model/model_file.h"
#include "isolab/model/output_selection.h"

namespace isolab::analysis {

struct RunDescription {
  const Problem* problem = nullptr;
  const model::AnalysisSection* analysis = nullptr;
  const integrators::RunSummary* summary = nullptr;
  const ResponsePeaks* peaks = nullptr;  // of every step of the run
  std::string version;
  model::OutputSelection selection;  // what the file records
};

// Throws InputError({path}, ...) when the extension is not .h5, .hdf5 or .csv, or the path cannot
// be an output (atomic_file.h). Commands call it before the analysis.
void CheckResultsPath(const std::string& path);

// Writes a run held in memory: the history's rows as they are (its output_every is recorded;
// run.selection.every is not applied again). Throws InputError when the file cannot be written
// (or CheckResultsPath fails).
void WriteResultsFile(const std::string& path, const RunDescription& run,
                      const integrators::ResponseHistory& history);

class ResultsWriter;

// A results file written after its run: its rows, observed as the run goes,
// stay in memory as compact as the file holds them (the selected histories of one run), and
// Write creates the file and writes each history as one chunk. A study's runs use it so that no
// HDF5 call happens while a run computes.
class HeldResultsFile final : public integrators::ResponseObserver {
 public:
  // As ResultsWriter (results_writer.h): checks the path and the selection (InputError), creates
  // nothing yet. `run.problem` must outlive this object; the rest of `run` is read only here.
  HeldResultsFile(const std::string& path, const RunDescription& run);
  ~HeldResultsFile() override;
  HeldResultsFile(HeldResultsFile&&) noexcept;
  HeldResultsFile& operator=(HeldResultsFile&&) noexcept;

  void Observe(const integrators::ResponseRow& row) override;
  // Writes the file of the run `run` describes, complete (summary and peaks); once. Throws
  // InputError or ResourceError when it cannot be written.
  void Write(const RunDescription& run);

 private:
  std::unique_ptr<ResultsWriter> writer_;
};

// Every warning about the model and the run (model_summary.h), for printing and the files.
std::vector<std::string> RunWarnings(const RunDescription& run);

}  // namespace isolab::analysis
