// SUNDIALS IDA (variable-order, variable-step BDF; its IDAS variant, for the energy quadratures)
// on the structure written in rate form (hysteresis/rate_form.h), with every phase change of every
// law located as a root and the integrator restarted there (IDAReInit), so its error control only
// ever sees a smooth system. The independent second integrator against which Newmark is checked:
// its accuracy is set by a tolerance, not a step.
//
// Output at the grid's times (TimeGrid: every output_every steps of dt), each reached exactly
// (IDASetStopTime), as is every sample time of the excitation, where its linear interpolation has a
// kink. The Jacobian is the exact one of the rate form, factorised by SuiteSparse KLU
// (SUNLinSol_KLU).
#pragma once

#include "isolab/integrators/excitation.h"
#include "isolab/integrators/response.h"
#include "isolab/structure/structure.h"

namespace isolab::integrators {

struct IdaOptions {
  double relative_tolerance = 1e-6;  // IDA rtol; (0, 0.1)
  // IDA atol, the same number for every state: displacements and slider positions (length),
  // velocities (length/time) and Bouc-Wen forces (force); > 0.
  double absolute_tolerance = 1e-9;
  double max_step = 0.0;    // largest internal step (time); 0 for no limit
  long max_steps = 100000;  // internal steps allowed between two stop times, >= 1

  // Throws InvalidParameter naming the first field out of range.
  void Validate() const;
};

// Runs from rest over the grid; a failure of IDA (error test or nonlinear solver failing
// repeatedly, too much work) stops the run with the call, the SUNDIALS flag name and the time,
// keeping the rows observed so far. RunSummary.steps counts grid steps completed (whole output
// intervals). The observer sees the state at rest and at every output time. Every law needs a rate
// form (hysteresis::HasRateForm): the caller checks.
RunSummary RunIda(const structure::Structure& structure, const Excitation& excitation,
                  const TimeGrid& grid, const IdaOptions& options, ResponseObserver& observer);
// The same, keeping every output row in memory.
RunSummary RunIda(const structure::Structure& structure, const Excitation& excitation,
                  const TimeGrid& grid, const IdaOptions& options, ResponseHistory* response);

}  // namespace isolab::integrators
