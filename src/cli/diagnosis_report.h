// The diagnosis written for a reader (Markdown) and for programs (JSON): the base fit, each step
// with its evidence and the e^2 it closed, the candidates weighed, the energy and secant
// stiffness of every test measured against the base and final models, and where in the loop the
// residual lies before and after.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/diagnosis/diagnose.h"

namespace isolab::cli {

struct DiagnosisContext {
  std::vector<std::string> data_files;
  std::string base_file;
  std::string model_file;  // where the final model was written
  unsigned seed = 1;
  UnitSystem units{"kN", "mm", "s"};
};

nlohmann::json DiagnosisJson(const diagnosis::Diagnosis& d, const identification::FitData& data,
                             const DiagnosisContext& context);

std::string DiagnosisMarkdown(const diagnosis::Diagnosis& d, const identification::FitData& data,
                              const DiagnosisContext& context);

}  // namespace isolab::cli
