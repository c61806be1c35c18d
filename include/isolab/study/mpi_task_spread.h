// A fit's tasks (identification/task_spread.h) over the ranks of mpirun: each rank runs the
// islands and Jacobian columns it owns and all ranks exchange their outputs, so every rank ends
// with the result of one process. MPI is initialised at the spread's first task (after a fit's
// inputs are read and checked) and finalised when the spread is destroyed.
#pragma once

#include <memory>

#include "isolab/identification/task_spread.h"

namespace isolab::study {

// Throws std::runtime_error when MPI cannot be initialised.
std::unique_ptr<identification::TaskSpread> MakeMpiTaskSpread();

}  // namespace isolab::study
