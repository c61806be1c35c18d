// `isolab diagnose --base`'s workflow, which the command line and Python's isolab.diagnose share:
// the cyclic tests read and checked as the cyclic fit reads them (cyclic/test_data_checks.h),
// every cycle kept (diagnosis::AllCycles), the base fit's size and work checked, the diagnosis
// run (diagnosis/diagnose.h) and the context its report names. The fronts parse their options
// into a CyclicDiagnosisRequest and render the report; the command line also writes its files.
#pragma once

#include <string>
#include <vector>

#include "isolab/cyclic/cyclic_fit.h"
#include "isolab/diagnosis/diagnose.h"
#include "isolab/diagnosis/report.h"

namespace isolab::cyclic {

struct CyclicDiagnosisRequest {
  std::vector<std::string> data;  // CSV files of cyclic tests
  std::string base_path;          // the base model's component types (YAML, as fit --model)
  std::string specimen;           // "sequential", "independent"; empty: the data's header
  // Of the data, unless a file's "# units:" line says; a file without one needs both.
  std::string force_unit, length_unit;
  diagnosis::DiagnoseOptions settings;  // seed, budget, threads and progress
  bool force = false;                   // diagnose beyond the work limit
  CyclicFitOptionNames names;           // units and force (cycles do not apply)
};

// The tests, the base and the base fit's work, checked and ready to diagnose.
struct CyclicDiagnosisProblem {
  CyclicDiagnosisRequest request;
  model::FitSpec base;
  identification::FitData data;
  FitWork work;
};

// Reads and checks the tests and the base; throws InputError naming the file, or the option by
// `request.names`.
CyclicDiagnosisProblem PrepareCyclicDiagnosis(CyclicDiagnosisRequest request);

// The diagnosis; a model the base cannot make of the data is an InputError naming the base.
diagnosis::Diagnosis DiagnoseCyclicTests(const CyclicDiagnosisProblem& problem);

// Names the diagnosis in its report's context: the data, the base, the seed and the base's
// units; the files and notes a front put there are left as they are.
void NameCyclicDiagnosis(const CyclicDiagnosisProblem& problem, diagnosis::ReportContext* context);

}  // namespace isolab::cyclic
