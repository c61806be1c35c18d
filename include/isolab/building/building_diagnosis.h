// The discrepancy workflow (diagnosis/diagnose.h) on a building's shake-table motions rather than
// an isolator's own loop:
//  1. the building is fitted by output error (building_fit.h) with the isolation the model has;
//  2. each motion's isolator loop is reconstructed with the masses that fit identified, not
//     nominal ones: the slab's measured displacement against minus the sum over levels of the
//     fitted mass times the measured absolute acceleration, per bearing;
//  3. the catalogue's detectors read those loops, and the effects they support are added and
//     refitted to the loops as an isolator diagnosis does (its BIC, guards and verdict);
//  4. an effect the loops name is then put to the building: the building, with the diagnosed
//     isolation, is refitted by output error (the specification's parameters and the added
//     components'), and the effect stands only if the building's own information criterion falls
//     by the diagnosis's margin. A loop that improves while the floor responses do not is a
//     reconstruction artefact (a mass or a channel), not an effect of the device, and is not
//     named.
// BIC at the building level is n ln(J) + p ln n, J the mean NRMSE^2 over the fitted channels, p
// the parameters the fit frees and n the effective samples of the residual (the smaller of the
// two fits', as the isolator diagnosis counts them): correlated model error is worth far fewer
// samples than it has.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/building/building_fit.h"
#include "isolab/diagnosis/diagnose.h"

namespace isolab::building {

struct BuildingDiagnosis {
  BuildingFitResult base;                  // the building with the model's isolation, fitted
  identification::FitData loops;           // per motion, the isolator's loop (per bearing)
  diagnosis::Diagnosis isolator;           // the catalogue on those loops
  std::vector<std::string> added;          // components the loops' diagnosis added
  std::optional<BuildingFitResult> refit;  // the building with the diagnosed isolation
  int base_parameters = 0, refit_parameters = 0;
  double samples = 0.0;  // the effective samples the BICs count
  double bic_base = 0.0, bic_refit = 0.0;
  bool confirmed = false;  // the refit lowers the building's BIC by the margin
  std::string conclusion;  // one sentence with the numbers

  const model::ModelFile& Final() const { return confirmed ? refit->fitted : base.fitted; }
};

// Throws InputError for a spec or motions the building fit refuses, for force-driven tests and
// motions without every level's acceleration (the loop cannot be reconstructed), and for an
// isolation the catalogue cannot refit (a Bouc-Wen component).
BuildingDiagnosis DiagnoseBuilding(const model::ModelFile& model,
                                   const std::vector<BuildingMotion>& motions,
                                   const BuildingFitSpec& spec,
                                   const identification::FitOptions& fit,
                                   const diagnosis::DiagnoseOptions& options);

}  // namespace isolab::building
