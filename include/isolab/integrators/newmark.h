// Newmark-beta time stepping with Newton-Raphson iteration on the effective residual
// (Chopra 2012, Sec. 5.7, Table 5.7.2):
//   R(u) = p_eff(t+h) - M a(u) - f(u, v(u)),   a = (u - u_n)/(beta h^2) - v_n/(beta h) - (1/(2
//   beta) - 1) a_n, v = gamma/(beta h) (u - u_n) + (1 - gamma/beta) v_n + h (1 - gamma/(2 beta))
//   a_n, K_eff = K_t + gamma/(beta h) C_t + M/(beta h^2),
// with the tangent assembled into a fixed sparse pattern and factorised by a linear solver chosen
// once per run from that pattern (dense LU for small systems, banded LU for narrow bands, KLU
// otherwise: src/integrators/tangent_solver.h). Newton stops when
// the residual is within force_tolerance of the step's force scale, when a correction is within
// displacement_tolerance, or when the residual is at the round-off of its own evaluation,
// 2 eps || |K_eff| |u| ||_inf (only reached where the force tolerance is out of floating-point
// reach: tall, flexible buildings, very fine steps). A step that does not converge is reverted
// and cut in halves (each half cut again if it fails), up to max_step_cuts levels.
#pragma once

#include "isolab/integrators/excitation.h"
#include "isolab/integrators/response.h"
#include "isolab/structure/structure.h"

namespace isolab::integrators {

struct NewmarkOptions {
  enum class Newton {
    kFull,             // tangent at every iteration (factorised again where its values changed)
    kModifiedInitial,  // tangent of the initial state, factorised once per run (again for each
                       // new step size after a step cut)
    kModifiedStep,     // tangent at each step's predictor, factorised once per step
  };

  // The factorisation of the effective tangent. kAuto chooses from the tangent's sparsity pattern
  // once per run; the others force one (for tests and measurements: every solver gives the same
  // response to round-off, at different costs).
  enum class LinearSolver {
    kAuto,
    kKlu,     // SuiteSparse KLU, any pattern
    kDense,   // dense LU with partial pivoting, O(n^3): small systems only
    kBanded,  // banded LU with partial pivoting within the pattern's bandwidths
  };

  double beta = 0.25;  // 1/4 average acceleration, 1/6 linear acceleration; (0, 0.5]
  double gamma = 0.5;  // >= 0.5; 0.5 for no numerical damping
  Newton newton = Newton::kFull;
  double force_tolerance = 1e-10;         // residual norm / force scale of the step; (0, 1)
  double displacement_tolerance = 1e-12;  // correction norm / displacement scale; (0, 1)
  int max_iterations = 30;                // Newton iterations per attempt, >= 1
  LinearSolver linear_solver = LinearSolver::kAuto;  // see LinearSolver
  // Levels of halving a step that does not converge, in [0, kMaxStepCuts]: a step may take up to
  // 2^(max_step_cuts + 1) attempts, so the bound keeps a failing run's time finite.
  int max_step_cuts = 8;
  static constexpr int kMaxStepCuts = 20;

  static NewmarkOptions AverageAcceleration() { return {}; }
  static NewmarkOptions LinearAcceleration() {
    NewmarkOptions options;
    options.beta = 1.0 / 6.0;
    return options;
  }

  // Throws InvalidParameter naming the first field out of range.
  void Validate() const;
};

// Runs from rest over the grid, handing the observer the state at rest and after every step (the
// grid's output_every is for the observer to apply).
RunSummary RunNewmark(const structure::Structure& structure, const Excitation& excitation,
                      const TimeGrid& grid, const NewmarkOptions& options,
                      ResponseObserver& observer);
// The same, keeping every output_every-th step in memory.
RunSummary RunNewmark(const structure::Structure& structure, const Excitation& excitation,
                      const TimeGrid& grid, const NewmarkOptions& options,
                      ResponseHistory* response);

}  // namespace isolab::integrators
