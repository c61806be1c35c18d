// The diagnosis generators' data in process: each truth in models/diagnosis/ driven through the
// protocol of scripts/generate_diagnosis_cases.sh (6 amplitudes x 2 periods, 3 cycles, 200
// samples a cycle, 1 % Gaussian force noise with the case's seed), on fresh specimens or as one
// specimen's campaign. Keep the two in step.
#pragma once

#include <string>
#include <vector>

#include "isolab/diagnosis/discrepancy.h"
#include "isolab/identification/synthetic_tests.h"
#include "isolab/model/model_file.h"

namespace isolab::diagnosis {

struct HiddenEffectCase {
  std::string file;  // under models/diagnosis/
  unsigned seed = 1;
  // A campaign on one specimen: the twelve tests in protocol order, each from the state the
  // previous left (scripts/generate_diagnosis_cases.sh --sequential), diagnosed as such.
  bool one_specimen = false;
};

inline identification::SyntheticTestOptions DiagnosisProtocol(unsigned seed,
                                                              bool one_specimen = false) {
  identification::SyntheticTestOptions protocol{
      {10, 25, 50, 100, 150, 200}, {2.0, 0.5}, 3, 200, 0.01, seed};
  protocol.one_specimen = one_specimen;
  return protocol;
}

inline model::ModelFile HiddenEffectTruth(const HiddenEffectCase& c) {
  return model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) + "/models/diagnosis/" + c.file);
}

inline identification::FitData HiddenEffectData(const HiddenEffectCase& c) {
  return AllCycles(identification::SyntheticTests(HiddenEffectTruth(c).isolation,
                                                  DiagnosisProtocol(c.seed, c.one_specimen)),
                   c.one_specimen);
}

}  // namespace isolab::diagnosis
