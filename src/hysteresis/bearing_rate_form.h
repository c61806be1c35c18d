// Rate forms of the bearing laws with a strength that varies (friction pendulum, lead-rubber),
// dispatched from rate_form.cpp. Private to the hysteresis library.
#pragma once

#include "isolab/hysteresis/rate_form.h"

namespace isolab::hysteresis {

RateResponse Evaluate(const FrictionPendulum& law, const LawPhase& phase, double u, double v,
                      double z);
void Roots(const FrictionPendulum& law, const LawPhase& phase, double u, double v, double z,
           double* roots);
PhaseSwitch Switch(const FrictionPendulum& law, const LawPhase& phase, int root, double u, double v,
                   double z);

RateResponse Evaluate(const LeadRubber& law, const LawPhase& phase, double u, double v, double z,
                      double w, double t);
void Roots(const LeadRubber& law, const LawPhase& phase, double u, double v, double z,
           double* roots);
PhaseSwitch Switch(const LeadRubber& law, const LawPhase& phase, int root, double u, double v,
                   double z);

}  // namespace isolab::hysteresis
