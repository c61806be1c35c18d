// `isolab fit --model`'s workflow, which the command line and Python's isolab.fit share: the
// cyclic tests read and checked (cyclic/test_data_checks.h), the assembly's parameters
// identified (identification/fit.h), what the data do not identify, the energy per fitted span,
// the components the fit gave no stiffness dropped, the testing factors, the fitted model file
// and one JSON rendering. The fronts parse their options into a CyclicFitRequest and render the
// outcome; nothing else.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "isolab/cyclic/test_data_checks.h"
#include "isolab/identification/fit.h"
#include "isolab/identification/identifiability.h"
#include "isolab/identification/parametrisation.h"
#include "isolab/identification/testing_factors.h"
#include "isolab/model/fit_spec_file.h"

namespace isolab::cyclic {

// The names a front gives its options, for the messages that refuse them (the command line's by
// default).
struct CyclicFitOptionNames {
  std::string units = "--force-unit and --length-unit";
  // A refused cycle selection: where, and the message's prefix.
  std::string cycles_location = "command line", cycles_prefix = "--cycles: ";
  std::string force = "command line (--force)";
};

struct CyclicFitRequest {
  std::vector<std::string> data;  // CSV files of cyclic tests
  std::string spec_path;          // component types and counts (YAML)
  std::vector<int> cycles;        // 1-based; empty: SelectCycles' default
  std::string specimen;           // "sequential", "independent"; empty: the data's header
  // Of the data, unless a file's "# units:" line says; a file without one needs both.
  std::string force_unit, length_unit;
  identification::FitOptions search;  // seed, budget, threads and progress
  bool force = false;                 // fit beyond the work limit
  CyclicFitOptionNames names;
};

// The tests, the model and the work, checked and ready to fit.
struct CyclicFitProblem {
  CyclicFitRequest request;
  model::FitSpec spec;
  identification::FitData data;
  bool one_specimen = false;
  std::optional<identification::ModelParametrisation> model;
  FitWork work;
};

// Energy of a fitted span, measured and modelled: a whole cycle's loop area, or, for a history
// fitted whole (cycle 0), the work of the force over it.
struct CyclicFitEnergy {
  std::string test;
  int cycle = 0;
  double amplitude = 0.0, measured = 0.0, fitted = 0.0;
};

struct CyclicFitOutcome {
  identification::FitResult result;   // every component of the specification
  std::vector<std::string> findings;  // what the data do not identify; empty when none
  std::vector<CyclicFitEnergy> energy;
  identification::TestingFactors testing;
  // The model to write: the components the fit gave no stiffness dropped (e^2 unchanged).
  identification::FitResult written;
  std::vector<identification::ComponentSpec> kept;
  std::vector<std::string> notes;  // one per dropped component, then per simplified one
};

// Reads and checks the tests and the specification; throws InputError naming the file, or the
// option by `request.names`.
CyclicFitProblem PrepareCyclicFit(CyclicFitRequest request);

// The search's progress line on stderr, as both fronts print it (CMA-ES or polish, generation,
// evaluations, best e^2).
void PrintCyclicFitProgress(const identification::FitProgress& progress);

// Fits. Throws InputError when the fit leaves no component any stiffness.
CyclicFitOutcome FitCyclicTests(const CyclicFitProblem& problem);

// Writes the fitted model file at `path` (model/fitted_model_file.h): the kept components, a law
// the fit left simpler written as that law, with a note in `outcome.notes`.
void WriteCyclicFitModel(const std::string& path, const CyclicFitProblem& problem,
                         CyclicFitOutcome& outcome);

// What `isolab fit --json` prints and isolab.fit returns.
nlohmann::json CyclicFitJson(const CyclicFitProblem& problem, const CyclicFitOutcome& outcome);

}  // namespace isolab::cyclic
