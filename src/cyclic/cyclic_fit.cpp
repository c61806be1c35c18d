#include "isolab/cyclic/cyclic_fit.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>
#include <stdexcept>

#include "isolab/core/errors.h"
#include "isolab/cyclic/testing_factors_text.h"
#include "isolab/hysteresis/law_parameters.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/model/fitted_model_file.h"

namespace isolab::cyclic {
namespace {

std::vector<CyclicFitEnergy> EnergyPerSpan(const hysteresis::ParallelAssembly& model,
                                           const identification::FitData& data) {
  std::vector<CyclicFitEnergy> rows;
  const auto forces = identification::SimulateForces(model, data.tests, data.one_specimen);
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const auto& test = data.tests[i];
    const std::vector<double>& force = forces[i];
    for (const auto& span : data.fitted[i]) {
      int cycle = 0;
      for (std::size_t c = 0; c < test.cycles.size(); ++c) {
        const auto& whole = test.cycles[c];
        if (whole.begin == span.begin && whole.end == span.end) cycle = static_cast<int>(c) + 1;
      }
      rows.push_back({test.name, cycle, identification::SpanAmplitude(test.displacement, span),
                      identification::LoopEnergy(test.displacement, test.force, span),
                      identification::LoopEnergy(test.displacement, force, span)});
    }
  }
  return rows;
}

}  // namespace

CyclicFitProblem PrepareCyclicFit(CyclicFitRequest request) {
  CyclicFitProblem problem;
  problem.spec = model::LoadFitSpec(request.spec_path);
  io::CyclicTestSet set = ReadCheckedTests(request.data, request.force_unit, request.length_unit,
                                           problem.spec.units, request.names.units);
  problem.one_specimen = io::OneSpecimen(request.specimen, set.one_specimen);
  try {
    problem.data =
        identification::SelectCycles(std::move(set.tests), request.cycles, problem.one_specimen);
  } catch (const std::invalid_argument& error) {
    throw InputError({request.names.cycles_location}, request.names.cycles_prefix + error.what());
  }
  try {
    problem.model.emplace(problem.spec.components, identification::ScalesOf(problem.data));
  } catch (const std::invalid_argument& error) {
    throw InputError({problem.spec.path}, error.what());
  }
  RequireMoreSamplesThanParameters(problem.data, *problem.model, problem.spec.path);
  problem.work = EstimateFitWork(*problem.model, problem.data, request.search);
  RequireWorkWithin(problem.work, kWorkLimit, request.force, request.names.force);
  problem.request = std::move(request);
  return problem;
}

void PrintCyclicFitProgress(const identification::FitProgress& p) {
  fmt::print(stderr, "  {} generation {:5d}, {:8d} evaluations, best e^2 = {:.6g} %\n",
             p.polishing ? "polish    " : "CMA-ES    ", p.generation, p.evaluations, 100 * p.best);
}

CyclicFitOutcome FitCyclicTests(const CyclicFitProblem& problem) {
  const identification::ModelParametrisation& model = *problem.model;
  const model::FitSpec& spec = problem.spec;
  CyclicFitOutcome outcome;
  try {
    outcome.result = identification::Fit(model, problem.data, problem.request.search);
  } catch (const std::invalid_argument& error) {
    throw InputError({problem.request.data.front()}, error.what());
  }
  const identification::FitResult& result = outcome.result;
  outcome.findings = identification::AssessIdentifiability(model, problem.data, result).Findings();
  outcome.energy = EnergyPerSpan(model.Assembly(result.point, result.amplitudes), problem.data);
  outcome.testing = identification::TestingFactorsOf(problem.data.tests);
  // Components the fit gave no stiffness carry no force: dropped, with a note, e^2 unchanged.
  const std::vector<std::size_t> zero = identification::ZeroComponents(model, result.amplitudes);
  for (const std::size_t c : zero) {
    outcome.notes.push_back(fmt::format(
        "{} ({}) was dropped: the fit gave it no stiffness, so the data need no such component",
        spec.components[c].name, hysteresis::LawName(spec.components[c].type)));
  }
  outcome.written = result;
  outcome.kept = spec.components;
  if (!zero.empty()) {
    if (zero.size() == spec.components.size()) {
      throw InputError({spec.path},
                       "the fit gave every component zero stiffness: the data have "
                       "no force these laws can carry");
    }
    outcome.kept = identification::DropComponents(model, zero, &outcome.written);
  }
  return outcome;
}

void WriteCyclicFitModel(const std::string& path, const CyclicFitProblem& problem,
                         CyclicFitOutcome& outcome) {
  const CyclicFitRequest& request = problem.request;
  const identification::FitResult& result = outcome.written;
  const identification::FitData& data = problem.data;
  model::FittedModel model;
  model.comment.push_back(fmt::format(
      "Identified by isolab fit from {} (specification {}, seed {}, {} evaluations).",
      fmt::join(request.data, ", "), problem.spec.path, request.search.seed, result.evaluations));
  std::string errors = fmt::format(
      "e^2 = {:.6g} % per test on average, {:.6g} % summed (Markou & Manolis 2016, Eq. 20)",
      100 * result.error.Mean(), 100 * result.error.total);
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    errors += fmt::format("{}{}: {:.4g} %", i == 0 ? "; per test: " : ", ", data.tests[i].name,
                          100 * result.error.per_test[i]);
  }
  model.comment.push_back(errors);
  for (std::string& line : TestingFactorsComment(outcome.testing, problem.spec.units)) {
    model.comment.push_back(std::move(line));
  }
  model.description = fmt::format("Fitted to {}", fmt::join(request.data, ", "));
  model.specification = problem.spec.path;
  model.units = problem.spec.units;
  model.range = identification::RangeOf(data);
  // A component the fit left a simpler law is written as that law.
  std::vector<std::string> names;
  std::vector<hysteresis::LawType> types;
  for (const auto& component : outcome.kept) {
    names.push_back(component.name);
    types.push_back(component.type);
  }
  std::vector<std::vector<double>> mathematical = result.mathematical;
  const std::vector<std::string> simplified =
      identification::SimplifyComponents(names, &types, &mathematical);
  model.components = outcome.kept;
  for (std::size_t c = 0; c < outcome.kept.size(); ++c) model.components[c].type = types[c];
  model.mathematical = mathematical;
  for (const std::string& note : simplified) model.comment.push_back(note + ".");
  model::WriteFittedModel(path, model);
  outcome.notes.insert(outcome.notes.end(), simplified.begin(), simplified.end());
}

nlohmann::json CyclicFitJson(const CyclicFitProblem& problem, const CyclicFitOutcome& outcome) {
  const identification::FitResult& result = outcome.result;
  const identification::FitData& data = problem.data;
  const model::FitSpec& spec = problem.spec;
  nlohmann::json json;
  json["e2"] = result.error.total;
  json["e2_mean"] = result.error.Mean();
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    json["e2_per_test"][data.tests[i].name] = result.error.per_test[i];
  }
  for (std::size_t c = 0; c < spec.components.size(); ++c) {
    const auto type = spec.components[c].type;
    const auto keys = hysteresis::ParameterKeys(type, hysteresis::ParameterForm::kMathematical);
    nlohmann::json parameters;
    for (std::size_t k = 0; k < keys.size(); ++k) {
      parameters[std::string(keys[k])] = result.mathematical[c][k];
    }
    json["components"].push_back({{"name", spec.components[c].name},
                                  {"type", hysteresis::LawName(type)},
                                  {"parameters", parameters}});
  }
  json["units"] = {{"force", spec.units.force()}, {"length", spec.units.length()}};
  for (const CyclicFitEnergy& row : outcome.energy) {
    json["energy_per_cycle"].push_back({{"test", row.test},
                                        {"cycle", row.cycle},
                                        {"amplitude", row.amplitude},
                                        {"measured", row.measured},
                                        {"fitted", row.fitted}});
  }
  const identification::IdentifiedRange range = identification::RangeOf(data);
  json["identified_range"] = {{"displacement", range.displacement},
                              {"velocity", range.velocity},
                              {"cycles", range.cycles},
                              {"data", range.data}};
  json["evaluations"] = result.evaluations;
  json["restarts"] = result.restarts;
  json["seconds"] = result.seconds;
  json["stop"] = result.stop == identification::FitStop::kConverged ? "converged" : "budget";
  json["stop_reason"] = result.stop_reason;
  json["identifiability"] = outcome.findings;
  json["testing_factors"] = TestingFactorsJson(outcome.testing);
  json["notes"] = outcome.notes;
  json["work"] = problem.work.Work();
  json["seed"] = problem.request.search.seed;
  json["one_specimen"] = problem.one_specimen;
  return json;
}

}  // namespace isolab::cyclic
