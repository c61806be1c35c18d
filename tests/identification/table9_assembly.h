// The paper's Table 9 nine-component system (testing::kTable9) as an assembly, with its three
// elastic springs (uy = 0, k0 >> k1, k2) in their exact trilinear form and its two k1 = k2 = 0
// components as elastoplastic elements: the truth of the synthetic HDRB tests.
#pragma once

#include <string>
#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"
#include "paper_tables.h"

namespace isolab::testing {

inline hysteresis::ParallelAssembly Table9ExactAssembly() {
  using hysteresis::LawType;
  std::vector<hysteresis::Component> components;
  for (int i = 0; i < 9; ++i) {
    const double* p = kTable9[i];
    LawType type = LawType::kThm1;
    std::vector<double> math(p, p + 5);
    if (p[3] == 0.0) {
      type = LawType::kTrilinearElastic;
      math = {p[1], p[2], p[4]};
    } else if (p[1] == 0.0 && p[2] == 0.0) {
      type = LawType::kElastoplastic;
      math = {p[0], p[3]};
    }
    components.push_back(
        {"c" + std::to_string(i + 1),
         hysteresis::LawParameters::Make(type, hysteresis::ParameterForm::kMathematical, math)});
  }
  return hysteresis::ParallelAssembly(std::move(components));
}

}  // namespace isolab::testing
