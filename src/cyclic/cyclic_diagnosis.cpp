#include "isolab/cyclic/cyclic_diagnosis.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <stdexcept>

#include "isolab/core/errors.h"
#include "isolab/io/cyclic_test_file.h"

namespace isolab::cyclic {

CyclicDiagnosisProblem PrepareCyclicDiagnosis(CyclicDiagnosisRequest request) {
  CyclicDiagnosisProblem problem;
  problem.base = model::LoadFitSpec(request.base_path);
  io::CyclicTestSet set = ReadCheckedTests(request.data, request.force_unit, request.length_unit,
                                           problem.base.units, request.names.units);
  const bool one_specimen = io::OneSpecimen(request.specimen, set.one_specimen);
  try {
    problem.data = diagnosis::AllCycles(std::move(set.tests), one_specimen);
  } catch (const std::invalid_argument& error) {
    throw InputError({fmt::format("{}", fmt::join(request.data, ", "))}, error.what());
  }
  try {
    const identification::ModelParametrisation parametrisation(
        problem.base.components, identification::ScalesOf(problem.data));
    RequireMoreSamplesThanParameters(problem.data, parametrisation, request.base_path);
    identification::FitOptions fit;
    fit.budget = request.settings.budget;
    fit.threads = request.settings.threads;
    problem.work = EstimateFitWork(parametrisation, problem.data, fit);
  } catch (const std::invalid_argument& error) {
    throw InputError({request.base_path}, error.what());
  }
  RequireWorkWithin(problem.work, kWorkLimit, request.force, request.names.force);
  problem.request = std::move(request);
  return problem;
}

diagnosis::Diagnosis DiagnoseCyclicTests(const CyclicDiagnosisProblem& problem) {
  try {
    return diagnosis::Diagnose(problem.base.components, problem.data, problem.request.settings);
  } catch (const std::invalid_argument& error) {
    throw InputError({problem.request.base_path}, error.what());
  }
}

void NameCyclicDiagnosis(const CyclicDiagnosisProblem& problem, diagnosis::ReportContext* context) {
  context->data_files = problem.request.data;
  context->base_file = problem.request.base_path;
  context->seed = problem.request.settings.seed;
  context->force_unit = problem.base.units.force();
  context->length_unit = problem.base.units.length();
}

}  // namespace isolab::cyclic
