// A building diagnosis's report as its users read it: the isolator's report (diagnosis/report.h)
// headed by the building's part of the story, and its JSON with the "building" object.
// `isolab diagnose --building` writes and prints them and isolab.diagnose(building=...) returns
// the JSON parsed: one function each, so that the two cannot drift.
#pragma once

#include <string>

#include "isolab/building/building_diagnosis.h"
#include "isolab/diagnosis/report.h"

namespace isolab::building {

// The report on the loops, the building's lines (its fit, how the loops were reconstructed, its
// refit and the conclusion) put before the context's own notes.
diagnosis::DiagnosisReport BuildBuildingReport(const BuildingDiagnosis& result,
                                               diagnosis::ReportContext context);

// The report's JSON (indented by two, no final newline) with "building": "base" and, when the
// diagnosis added an effect, "refit" (objective_start, objective, effective_samples, parameters,
// channels), "added", "confirmed", "bic_base", "bic_refit", "effective_samples", "conclusion".
std::string BuildingDiagnosisJson(const BuildingDiagnosis& result,
                                  const diagnosis::DiagnosisReport& report);

}  // namespace isolab::building
