#pragma once
// What one time step did, for the log line of the step and for stepWithRetry.
#include <cstddef>
#include <vector>

#include "linearSolvers/SolverPerformance.hpp"

namespace isph {

struct StepReport {
  std::vector<SolverPerformance> viscous;  // the implicit deviatoric term, one per component
  SolverPerformance ppe;
  std::size_t freeSurface = 0;
  std::size_t collisions = 0;  // material particles separated from a too-close neighbour
  std::size_t wallSafeguard = 0;
  std::size_t wallCrossings = 0;  // this step
  double maxShift = 0;  // in dx
  double densityVariation = -1;  // wcsph: the largest |ρ/ρ0 − 1| of the material (−1: isph)
  double maxSpeed = 0;
  double courant = 0;

  // The first solve of the step that did not converge (the viscous ones, then the PPE), or
  // null: the particles are then as at the step start (stepWithRetry redoes the step).
  const SolverPerformance* failedSolve() const {
    for (const auto& v : viscous) {
      if (!v.converged) return &v;
    }
    return ppe.converged ? nullptr : &ppe;
  }
};

}  // namespace isph
