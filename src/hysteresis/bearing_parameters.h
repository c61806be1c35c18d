// The parameters of the bearing presets (friction_pendulum, lead_rubber, hdr_bearing): keys,
// rules, conversion between forms and kernels. Private to the hysteresis library;
// law_parameters.cpp dispatches to these for the three types.
#pragma once

#include <string_view>

#include "isolab/hysteresis/law_kernel.h"
#include "isolab/hysteresis/law_parameters.h"
#include "rule_checker.h"

namespace isolab::hysteresis {

bool IsBearingPreset(LawType type);
Keys BearingKeys(LawType type, ParameterForm form);
// Keys that may be left out (NaN): alternatives (mu or mu_slow, mu_fast, a), the optional heating
// of the lead core, defaults (e2, yield_strain). Their rules are checked by ValidateBearing.
bool BearingKeyMayBeOmitted(LawType type, std::string_view key);
void ValidateBearing(LawType type, ParameterForm form, const ParameterArray& values);
ParameterArray ConvertBearing(LawType type, ParameterForm to, const ParameterArray& values);
LawKernel BearingKernel(LawType type, const ParameterArray& mechanical);

}  // namespace isolab::hysteresis
