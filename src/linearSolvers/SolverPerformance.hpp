#pragma once
// What one linear solve did, logged as one line in OpenFOAM's form:
//   BoomerAMG-PCG:  Solving for p, Initial residual = 0.0123, Final residual = 3.2e-09, No
//   Iterations 7
// Residuals are normalised, ||b - A x||_2 / ||b||_2 (see LinearSolver.hpp).
#include <string>

namespace isph {

struct SolverPerformance {
  std::string solverName;  // e.g. "BoomerAMG-PCG", "Eigen-BiCGSTAB"
  std::string field;       // e.g. "p"
  double initialResidual = 0, finalResidual = 0;
  int iterations = 0;
  bool converged = false;
  // Wall-clock seconds spent building the solver's matrix (hypre IJ assembly, Eigen copy),
  // setting up the preconditioner or factorisation, and iterating. Not part of str().
  double assemblySeconds = 0, setupSeconds = 0, solveSeconds = 0;
  // ... and checking it: the system's shape and values before the solve, and our own
  // residual norms before and after (ControlledLinearSolver.hpp).
  double checkSeconds = 0;
  double seconds() const { return assemblySeconds + setupSeconds + solveSeconds + checkSeconds; }

  std::string str() const;
};

// Log str() with isph::info, and a warning when the solve did not converge.
void logSolverPerformance(const SolverPerformance& performance);

}  // namespace isph
