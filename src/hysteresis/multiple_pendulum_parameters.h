// The parameters of the multiple pendulum presets (double_friction_pendulum,
// triple_friction_pendulum, multiple_pendulum.h): keys, rules and kernels. The same keys in both
// forms. Private to the hysteresis library; law_parameters.cpp dispatches to these for the two
// types.
#pragma once

#include "isolab/hysteresis/law_kernel.h"
#include "isolab/hysteresis/law_parameters.h"
#include "rule_checker.h"

namespace isolab::hysteresis {

bool IsMultiplePendulum(LawType type);
Keys MultiplePendulumKeys(LawType type);
void ValidateMultiplePendulum(LawType type, const ParameterArray& values);
LawKernel MultiplePendulumKernel(LawType type, const ParameterArray& values);

}  // namespace isolab::hysteresis
