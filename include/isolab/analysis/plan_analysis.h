// From a plan model file to what Newmark runs (plan_structure.h, plan_excitation.h), and what a
// plan run yields: the isolators' displacement vectors and their peak resultants, the floors'
// rotations, the torsional amplification, and the results file.
//
// The two components are turned to the building's axes: with H1 at `angle` from x (H2 at
// angle + 90 degrees), a_gx = cos(angle) H1 - sin(angle) H2, a_gy = sin(angle) H1 + cos(angle)
// H2. A pair must share its step and its length (PEER's pairs do): anything else is refused.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/analysis/analysis_setup.h"
#include "isolab/analysis/response_peaks.h"
#include "isolab/integrators/ida.h"
#include "isolab/integrators/newmark.h"
#include "isolab/integrators/plan_excitation.h"
#include "isolab/io/record.h"
#include "isolab/model/model_file.h"
#include "isolab/model/plan_model_file.h"
#include "isolab/structure/plan_structure.h"

namespace isolab::analysis {

struct PlanOverrides {
  std::optional<double> scale;  // replaces both components' scales
  std::optional<double> dt;     // replaces analysis.dt (model time unit)
  std::optional<model::FreeVibration> free_vibration;
  std::optional<double> trial_displacement;   // model length; default 0.1 m
  std::int64_t max_steps = kDefaultMaxSteps;  // the most analysis steps (StepGrid)
};

struct PlanAnalysisSetup {
  structure::PlanStructure structure;
  integrators::PlanExcitation excitation;
  integrators::TimeGrid grid;
  io::AppliedRecord h1, h2;  // h2.path empty for one component
  double angle = 0.0;        // degrees from x to H1
  double total_mass = 0.0;
  double trial_displacement = 0.0;  // (length)
  // 2 pi sqrt(total mass / secant stiffness of all isolators along x at the trial displacement):
  // the building as a rigid block on its isolators.
  double isolated_period = 0.0;
  double excitation_end = 0.0;
  double free_vibration = 0.0;
};

// Throws InputError for records that cannot be read, a pair with different steps or lengths, a
// dt coarser than the records' and a model without excitation.
PlanAnalysisSetup PreparePlanAnalysis(const model::PlanModelFile& model,
                                      const PlanOverrides& overrides);

// Newmark or IDA on the plan structure, as `analysis` (the model's, or with the command line's
// overrides) says. Throws InputError for IDA on a law without a rate form.
integrators::RunSummary RunPlanAnalysis(const model::AnalysisSection& analysis,
                                        const PlanAnalysisSetup& setup,
                                        integrators::ResponseHistory* response);

struct PlanPeaks {
  std::vector<Peak> isolator_resultant;  // per isolator: peak of |(u_x, u_y)|
  Peak centre_resultant;                 // of the base at its centre of mass
  Peak largest_resultant;                // the largest isolator's (index: the isolator)
  // largest_resultant / centre_resultant: how much the base's twist adds at the worst isolator.
  double torsional_amplification = 0.0;
  std::vector<Peak> floor_rotation;  // per floor, base first (radians)
  Peak largest_floor_rotation;       // the largest floor's (index: the floor, 0 the base)
  Peak base_shear;                   // peak resultant of the isolators' summed force
};

PlanPeaks ComputePlanPeaks(const PlanAnalysisSetup& setup,
                           const integrators::ResponseHistory& response);

// Throws InputError unless `path` can be a plan run's results file (.h5 or .hdf5; atomic_file.h).
void CheckPlanResultsPath(const std::string& path);

// The HDF5 results of a plan run (docs/results.md, "Plan models"). Throws InputError when the
// file cannot be written or the path is not .h5/.hdf5.
void WritePlanResults(const std::string& path, const model::PlanModelFile& model,
                      const PlanAnalysisSetup& setup, const integrators::ResponseHistory& response,
                      const integrators::RunSummary& summary, const PlanPeaks& peaks,
                      const std::string& version);

}  // namespace isolab::analysis
