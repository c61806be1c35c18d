// Uses the installed isolab as a library: loads a model file and runs its cyclic test. Exits 0
// when the second cycle dissipates the paper's Table 7 value, W_d = 9920 kN mm (THM1, hardening).
#include <cmath>
#include <cstdio>

#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/model/model_file.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: isolab_consumer models/paper/table7_thm1_hard.yaml\n");
    return 2;
  }
  const isolab::model::ModelFile model = isolab::model::LoadModelFile(argv[1]);
  const isolab::hysteresis::CyclicResult result =
      isolab::hysteresis::RunCyclicTest(model.isolation, *model.cyclic);
  const double dissipated = result.cycles.at(1).dissipated;
  std::printf("W_d of cycle 2: %.6g kN mm (paper: 9920)\n", dissipated);
  return std::abs(dissipated - 9920.0) < 1e-6 * 9920.0 ? 0 : 1;
}
