// isolab.run and its Result: a model's time-history analysis, with the response as numpy arrays
// that view the result's own storage (no copy) wherever it is stored so.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <memory>
#include <optional>

#include "arrays.h"
#include "bindings.h"
#include "isolab/analysis/problem.h"
#include "isolab/analysis/result_series.h"
#include "isolab/analysis/results_file.h"
#include "isolab/analysis/run_band.h"
#include "isolab/analysis/run_report.h"
#include "isolab/analysis/solve.h"
#include "isolab/core/errors.h"
#include "isolab/io/output_check.h"
#include "isolab/model/free_vibration_text.h"
#include "model.h"
#include "record_argument.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

// Everything a run made, in one place that does not move: the series refer into it.
struct RunResult {
  analysis::Problem problem;
  model::AnalysisSection analysis;
  integrators::ResponseHistory response;
  analysis::Summary summary;
  std::vector<analysis::Series> series;
  std::optional<analysis::RunBand> band;  // samples=: the peaks' spread over drawn parameters
  unsigned seed = 1;
  // The files the run read (the model, its isolation files, its records): save() never writes
  // over one, as `isolab run -o` never does.
  std::vector<std::string> inputs;

  analysis::RunDescription Description() const {
    return {&problem, &analysis, &summary.run, &summary.peaks, ISOLAB_VERSION, {}};
  }
  const analysis::Series& Find(const std::string& name) const {
    for (const analysis::Series& s : series) {
      if (s.name == name) return s;
    }
    throw py::key_error(name);
  }
};

struct RunOptions {
  analysis::RunOverrides overrides;
  std::optional<std::string> integrator;
  std::optional<double> rtol, atol;
  int samples = 0;  // parameter sets drawn from the model's uncertainty; 0: no band
  unsigned seed = 1;
};

std::shared_ptr<RunResult> Run(const Model& model, const RunOptions& options) {
  const model::AnalysisSection analysis = analysis::ChooseIntegrator(
      model.file().analysis, {options.integrator.value_or(""), options.rtol, options.atol}, "");
  if (options.samples > 0) analysis::CheckRunBand(model.file());
  std::shared_ptr<RunResult> result;
  {
    py::gil_scoped_release release;  // a thread pool of runs scales
    result = std::make_shared<RunResult>(RunResult{
        analysis::Prepare(model.file(), options.overrides), analysis, {}, {}, {}, {}, 1, {}});
    integrators::HistoryRecorder recorder = integrators::RecordHistory(
        result->problem.structure, result->problem.grid, &result->response);
    integrators::ResponseObserver* const also[] = {&recorder};
    analysis::SolveOptions solve;
    solve.analysis = analysis;
    result->summary = analysis::Solve(solve, result->problem, also);
    result->seed = options.seed;
    if (options.samples > 0 && result->summary.ok()) {
      result->band = analysis::PredictRunBand(model.file(), options.overrides, analysis,
                                              options.samples, options.seed);
    }
  }
  result->series = analysis::ResultSeries(result->problem, model::OutputSelection{});
  result->inputs = model.file().included_files;
  result->inputs.push_back(model.file().path);
  for (const analysis::RecordOverride& record : options.overrides.records) {
    if (!record.file.empty()) result->inputs.push_back(record.file);
  }
  if (options.overrides.records.empty()) {
    const std::vector<std::string> records = model::RecordFiles(model.file());
    result->inputs.insert(result->inputs.end(), records.begin(), records.end());
  }
  return result;
}

// The history's own row-major storage of a series that is one of its matrices whole (what the
// series' sources say: analysis::WholeArray), its time or its axial loads, so the array can view
// it; nullptr for a series computed from the rows.
const double* StoredRows(const RunResult& r, const analysis::Series& series) {
  const integrators::ResponseHistory& h = r.response;
  const auto whole = [&](const integrators::RowMatrix& m) {
    return m.cols() == static_cast<Eigen::Index>(series.width()) ? m.data() : nullptr;
  };
  const std::vector<analysis::ColumnSource>& sources = series.sources;
  if (sources.size() == 1 && !sources[0].sum && sources[0].array == analysis::RowArray::kScalars &&
      sources[0].index == static_cast<int>(analysis::RowScalar::kTime)) {
    return h.time.data();
  }
  // Computed, not read off (a row may come without axial loads), yet every bearing's in order.
  if (series.name == "isolator/axial_load") return whole(h.axial_load);
  const std::optional<analysis::RowArray> array = analysis::WholeArray(series, r.problem.structure);
  if (!array) return nullptr;
  switch (*array) {
    case analysis::RowArray::kDisplacement:
      return whole(h.displacement);
    case analysis::RowArray::kVelocity:
      return whole(h.velocity);
    case analysis::RowArray::kAcceleration:
      return whole(h.acceleration);
    case analysis::RowArray::kAbsoluteAcceleration:
      return whole(h.absolute_acceleration);
    case analysis::RowArray::kConnectionForce:
      return whole(h.connection_force);
    case analysis::RowArray::kLawForce:
      return whole(h.law_force);
    case analysis::RowArray::kScalars:
      return nullptr;  // the energies are stored as structs
  }
  return nullptr;
}

// The values of a series over the rows written: a read-only view of the result's storage when
// the history stores the series as it is, else computed into a new array.
py::array SeriesArray(const std::shared_ptr<RunResult>& result, const analysis::Series& series) {
  const integrators::ResponseHistory& history = result->response;
  const py::ssize_t rows = history.rows_written;
  const py::ssize_t width = series.columns.empty() ? 0 : py::ssize_t(series.width());
  if (const double* stored = StoredRows(*result, series)) {
    return View(py::cast(result), stored, rows, width);
  }
  std::vector<py::ssize_t> shape = {rows};
  if (width > 0) shape.push_back(width);
  py::array array = py::array_t<double>(shape);
  double* out = static_cast<double*>(array.mutable_data());
  for (py::ssize_t row = 0; row < rows; ++row) {
    series.fill(history.Row(static_cast<int>(row)), out + row * std::max<py::ssize_t>(width, 1));
  }
  MakeReadOnly(array);
  return array;
}

// What `isolab run --json` prints (analysis::RunReport), as Python objects.
py::dict Summary(const RunResult& r) {
  nlohmann::json report = analysis::RunReport(r.problem, r.analysis, r.summary);
  if (r.band) report["band"] = analysis::RunBandJson(*r.band, r.seed);
  return py::module_::import("json").attr("loads")(report.dump());
}

// {series name: its field}, e.g. the units of every series.
template <typename Field>
py::dict BySeries(const RunResult& r, Field analysis::Series::*field) {
  py::dict values;
  for (const analysis::Series& s : r.series) values[py::str(s.name)] = s.*field;
  return values;
}

}  // namespace

void BindRun(py::module_& module) {
  py::class_<RunResult, std::shared_ptr<RunResult>>(
      module, "Result",
      "A run's response: result['displacement'] is a numpy array (rows: output times; columns: "
      "result.columns[name]) in result.units[name]. Response matrices are views of the result, "
      "not copies; every array is read-only.")
      .def_property_readonly("names",
                             [](const RunResult& r) {
                               std::vector<std::string> names;
                               for (const analysis::Series& s : r.series) names.push_back(s.name);
                               return names;
                             })
      .def_property_readonly(
          "units", [](const RunResult& r) { return BySeries(r, &analysis::Series::units); })
      .def_property_readonly(
          "columns", [](const RunResult& r) { return BySeries(r, &analysis::Series::columns); })
      .def("__getitem__", [](const std::shared_ptr<RunResult>& r,
                             const std::string& name) { return SeriesArray(r, r->Find(name)); })
      .def("__contains__",
           [](const RunResult& r, const std::string& name) {
             for (const analysis::Series& s : r.series) {
               if (s.name == name) return true;
             }
             return false;
           })
      .def_property_readonly("ok", [](const RunResult& r) { return r.summary.ok(); })
      .def_property_readonly("message", [](const RunResult& r) { return r.summary.run.message; })
      .def_property_readonly(
          "peaks", [](const RunResult& r) { return py::object(Summary(r)["peaks"]); },
          "The peaks `isolab run --json` prints: summary['peaks']")
      .def_property_readonly("summary", &Summary,
                             "What `isolab run --json` prints: the record as applied, the model "
                             "summary, peaks, energies, termination, integrator and its "
                             "statistics")
      .def_property_readonly("warnings", [](const RunResult& r) { return r.summary.warnings; })
      .def_property_readonly("model_units",
                             [](const RunResult& r) {
                               const UnitSystem& u = r.problem.units();
                               return py::dict(py::arg("force") = u.force(),
                                               py::arg("length") = u.length(),
                                               py::arg("time") = u.time());
                             })
      .def(
          "save",
          [](const RunResult& r, const std::filesystem::path& path) {
            io::CheckOutputs(r.inputs, {path.string()});
            analysis::WriteResultsFile(path.string(), r.Description(), r.response);
          },
          py::arg("path"),
          "Writes the results file `isolab run -o path` writes (.h5/.hdf5 or .csv)");

  module.def(
      "_run",
      [](const Model& model, const py::object& record, const py::object& h2,
         std::optional<double> angle, const std::optional<std::string>& units,
         std::optional<double> record_dt, std::optional<double> scale, std::optional<double> dt,
         const py::object& free_vibration, bool fixed_base,
         std::optional<double> trial_displacement, const std::optional<std::string>& integrator,
         std::optional<double> rtol, std::optional<double> atol, int samples, unsigned seed) {
        RunOptions options;
        if (samples != 0 && samples < 2) {
          throw InputError({"samples"}, "draws a band: 2 or more parameter sets");
        }
        options.samples = samples;
        options.seed = seed;
        analysis::RunOverrides& o = options.overrides;
        if (!h2.is_none() && record.is_none()) {
          throw InputError({"h2"}, "needs record: the pair's first component");
        }
        if (angle && record.is_none()) {
          throw InputError({"angle"}, "needs record (the model's own pair has its angle)");
        }
        // A pair's two components are both files or both arrays (sharing record_dt and units).
        for (const auto& [component, name] : {std::pair{&record, "record"}, {&h2, "h2"}}) {
          if (component->is_none()) continue;
          analysis::RecordOverride given;
          given.name = name;
          if (IsRecordFile(*component)) {
            given.file = py::str(*component).cast<std::string>();
          } else {
            given.data = ArrayRecord(*component, record_dt, units);
          }
          o.records.push_back(std::move(given));
        }
        o.angle = angle.value_or(0.0);
        if (record.is_none() || IsRecordFile(record)) {
          if (units) o.record_units = *units;
          if (record_dt) {
            o.record_dt = model.file().units.Convert(*record_dt, "s", dimension::kTime);
          }
        }
        o.units_given_by = "units";
        o.dt_given_by = "record_dt";
        o.names = {"dt",   "trial_displacement", "free_vibration", "angle", "fixed_base", "",
                   "scale"};
        o.scale = scale;
        o.dt = dt;
        o.fixed_base = fixed_base;
        o.trial_displacement = trial_displacement;
        if (!free_vibration.is_none()) {
          // "auto" or a number, read as the command line reads --free-vibration.
          o.free_vibration = model::ParseFreeVibration(py::str(free_vibration), model.file().units,
                                                       "free_vibration");
        }
        if (integrator && *integrator != "newmark" && *integrator != "ida") {
          throw InputError({"integrator"}, "'" + *integrator + "' (newmark or ida)");
        }
        options.integrator = integrator;
        options.rtol = rtol;
        options.atol = atol;
        return Run(model, options);
      },
      py::arg("model"), py::arg("record") = py::none(), py::arg("h2") = py::none(),
      py::arg("angle") = py::none(), py::arg("units") = py::none(),
      py::arg("record_dt") = py::none(), py::arg("scale") = py::none(), py::arg("dt") = py::none(),
      py::arg("free_vibration") = py::none(), py::arg("fixed_base") = false,
      py::arg("trial_displacement") = py::none(), py::arg("integrator") = py::none(),
      py::arg("rtol") = py::none(), py::arg("atol") = py::none(), py::arg("samples") = 0,
      py::arg("seed") = 1);
}

}  // namespace isolab::python
