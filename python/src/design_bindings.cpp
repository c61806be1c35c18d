// isolab.design: `isolab design` (bound models, ELF, a suite scaled to the target, every bound x
// eccentricity case x record on local threads, the design values and checks) with the command
// line's options as keyword arguments. It writes what the command line writes except the figures
// (scripts/plot_design.py draws them from the output folder) and returns the numbers.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>

#include "bindings.h"
#include "isolab/core/errors.h"
#include "isolab/core/worker_count.h"
#include "isolab/model/design_file.h"
#include "isolab/study/design.h"
#include "isolab/study/design_report.h"
#include "isolab/study/design_workflow.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

py::dict Design(const std::string& design_path, const std::string& output, int jobs, bool quiet) {
  const model::DesignFile design = model::LoadDesignFile(design_path);
  CheckedWorkers(jobs, "jobs");
  study::DesignRun run;
  {
    py::gil_scoped_release release;
    run = study::RunDesignIntoFolder(design, {output, "output", jobs, false, ISOLAB_VERSION},
                                     [&](const std::string& line) {
                                       if (!quiet) fmt::print(stderr, "{}\n", line);
                                     },
                                     {});
  }
  const study::DesignOutcome& outcome = run.outcome;
  if (!run.committed) {
    throw std::runtime_error(fmt::format("{} of {} design runs failed; no design values",
                                         outcome.failed, outcome.runs.size()));
  }

  const double second = 1.0 / design.model.units.SiFactor(dimension::kTime);  // model time per s
  py::dict bounds;
  for (std::size_t b = 0; b < outcome.bounds.size(); ++b) {
    const study::DesignBound& bound = outcome.bounds[b];
    py::dict values;
    for (const study::DesignQuantityInfo& info : study::DesignQuantities()) {
      values[py::str(std::string(info.key))] =
          outcome.values[b][static_cast<std::size_t>(info.quantity)].value;
    }
    py::dict elf(
        py::arg("D_M") = bound.elf.displacement, py::arg("T_M") = bound.elf.period / second,
        py::arg("beta_M") = bound.elf.at_design.damping, py::arg("B_M") = bound.damping_coefficient,
        py::arg("k_M") = bound.elf.at_design.stiffness, py::arg("V_b") = bound.elf.base_shear,
        py::arg("D_TM") = bound.elf_total_displacement);
    const py::object opensees =
        bound.opensees_file.empty() ? py::object(py::none()) : py::str(bound.opensees_file);
    bounds[py::str(bound.bound)] =
        py::dict(py::arg("model") = bound.model_file, py::arg("opensees") = opensees,
                 py::arg("elf") = elf, py::arg("values") = values);
  }
  py::list records;
  for (const study::DesignRecord& r : outcome.records) {
    records.append(py::dict(py::arg("name") = r.name, py::arg("files") = r.files,
                            py::arg("factor") = r.factor));
  }
  py::dict governing;
  for (const study::DesignQuantityInfo& info : study::DesignQuantities()) {
    governing[py::str(std::string(info.key))] =
        outcome.bounds[outcome.governing[static_cast<std::size_t>(info.quantity)]].bound;
  }
  py::list warnings;
  for (const study::DesignWarning& w : outcome.warnings) {
    warnings.append(py::dict(py::arg("bound") = outcome.bounds[w.bound].bound,
                             py::arg("text") = w.text, py::arg("runs") = w.runs));
  }
  const auto number = [](double v) -> py::object {
    return std::isnan(v) ? py::none() : py::cast(v);
  };
  const study::DesignChecks& c = outcome.checks;
  py::list checks;
  for (const study::DesignCheck& k : c.checks) {
    checks.append(py::dict(py::arg("check") = k.check, py::arg("clause") = k.clause,
                           py::arg("unit") = k.unit, py::arg("demand") = number(k.demand),
                           py::arg("limit") = number(k.limit), py::arg("basis") = k.basis,
                           py::arg("verdict") = std::string(study::VerdictName(k.verdict)),
                           py::arg("isolators") = k.isolators));
  }
  const auto design_value = [&](const study::DesignValue& v) {
    return py::dict(py::arg("value") = v.value, py::arg("bound") = outcome.bounds[v.bound].bound,
                    py::arg("response_history") = v.response_history, py::arg("factor") = v.factor,
                    py::arg("floor") = v.floor, py::arg("elf") = v.elf, py::arg("rule") = v.rule);
  };
  py::dict design_values(py::arg("D_TM") = design_value(c.total_displacement),
                         py::arg("V_b") = design_value(c.base_shear));
  if (c.superstructure) design_values["V_s"] = design_value(c.superstructure->v_s);
  py::list parts;
  for (const study::DesignPartValue& part : outcome.parts) {
    py::dict values;
    for (std::size_t b = 0; b < outcome.bounds.size(); ++b) {
      values[py::str(outcome.bounds[b].bound)] = number(part.bounds[b].value);
    }
    parts.append(py::dict(
        py::arg("quantity") = std::string(study::PartQuantityName(part.quantity)),
        py::arg("part") = part.part,
        py::arg("unit") = study::PartQuantityUnit(part.quantity, design.model.units),
        py::arg("values") = values, py::arg("governing") = outcome.bounds[part.governing].bound));
  }
  py::dict result;
  result["parts"] = parts;
  result["code"] = std::string(model::CodeName(design.code));
  result["design_values"] = design_values;
  result["checks"] = checks;
  result["warnings"] = warnings;
  result["opensees_refused"] =
      outcome.opensees_refused.empty() ? py::object(py::none()) : py::str(outcome.opensees_refused);
  result["bounds"] = bounds;
  result["governing"] = governing;
  result["records"] = records;
  result["period_range"] = py::make_tuple(outcome.period_range[0], outcome.period_range[1]);
  result["statistic"] = outcome.mean_of_suite ? "mean" : "max";
  result["summary"] = study::DesignSummaryText(design, outcome);
  result["output"] = run.folder;
  return result;
}

}  // namespace

void BindDesign(py::module_& module) {
  module.def("_design", &Design, py::arg("design"), py::arg("output"), py::arg("jobs"),
             py::arg("quiet"));
}

}  // namespace isolab::python
