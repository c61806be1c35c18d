// The diagnosis generators' data in process: each truth in models/diagnosis/ driven through the
// protocol of scripts/generate_diagnosis_cases.sh (6 amplitudes x 2 periods, 3 cycles, 200
// samples a cycle, 1 % Gaussian force noise with the case's seed). Keep the two in step.
#pragma once

#include <string>
#include <vector>

#include "isolab/diagnosis/discrepancy.h"
#include "isolab/identification/synthetic_tests.h"
#include "isolab/io/model_file.h"

namespace isolab::diagnosis {

struct HiddenEffectCase {
  std::string file;  // under models/diagnosis/
  unsigned seed = 1;
};

inline identification::SyntheticTestOptions DiagnosisProtocol(unsigned seed) {
  return {{10, 25, 50, 100, 150, 200}, {2.0, 0.5}, 3, 200, 0.01, seed};
}

inline identification::FitData HiddenEffectData(const HiddenEffectCase& c) {
  const io::ModelFile truth =
      io::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) + "/models/diagnosis/" + c.file);
  return AllCycles(identification::SyntheticTests(truth.isolation, DiagnosisProtocol(c.seed)));
}

}  // namespace isolab::diagnosis
