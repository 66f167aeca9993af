#pragma once
// A linear solver for A x = b, chosen by name in a sub-dictionary of system/isphSolution:
//
//   p
//   {
//       solver          PCG;         // PCG | GMRES | BiCGSTAB (hypre) | EigenCG | EigenBiCGSTAB |
//       EigenLU preconditioner  BoomerAMG;   // BoomerAMG | diagonal | none (hypre solvers)
//       tolerance       1e-8;
//       relTol          0;
//       maxIter         200;
//       reuseSetup      1;           // + BoomerAMG settings, see hypre/BoomerAMG.hpp
//   }
//
// Residual, the same for every solver: r = ||b - A x||_2 / max(||b||_2, tiny), computed by our
// own CSR mat-vec (SparseSystem.hpp) so that logs are comparable. The initial residual is
// that of the warm start x; the solve has converged when r <= tolerance or
// r <= relTol * r_initial, and stops after at most maxIter iterations. If b = 0 the solution is
// x = 0 (0 iterations). Not converging is not an error: the performance says so and the
// caller decides (logSolverPerformance warns).
#include <memory>
#include <string>
#include <vector>

#include "core/Registry.hpp"
#include "linearSolvers/SolverPerformance.hpp"
#include "linearSolvers/SparseSystem.hpp"

namespace isph {

class Dictionary;

// The stopping controls every solver reads (tolerance, relTol, maxIter).
struct LinearSolverControls {
  std::string field;        // the solved-for field, for the log ("p")
  double tolerance = 1e-6;  // numerics.md §5: 1e-8 for verification, 1e-6 in production
  double relTol = 0.0;
  int maxIter = 1000;

  // Read and check the controls (defaults echoed); FatalError at the keyword's line.
  static LinearSolverControls read(const Dictionary& dict, const std::string& field);
};

class LinearSolver {
 public:
  virtual ~LinearSolver();
  // x holds the initial guess (warm start; empty means zero) and receives the solution.
  virtual SolverPerformance solve(const SparseSystem& A, std::vector<double>& x) = 0;
  // As solve(), but to the tolerance alone (relTol 0): the final pass of a nonlinear
  // iteration whose earlier passes stop at relTol (OpenFOAM's UFinal).
  virtual SolverPerformance solveFinal(const SparseSystem& A, std::vector<double>& x) = 0;
  // Whether solve() may stop short of the tolerance (relTol > 0).
  virtual bool stopsAtRelTol() const = 0;
  // Solves so far, and AMG hierarchies built for them (0 for solvers that build none): the
  // log's record of what reuseSetup saved.
  virtual int solvesDone() const = 0;
  virtual int preconditionersBuilt() const { return 0; }
  virtual std::string name() const = 0;
  // A hint for the next solve only: its matrix differs little from the last one's (same
  // size and numbering, a few changed entries), so a preconditioner built for the last may
  // be kept. Solvers without a reusable preconditioner ignore it.
  virtual void keepPreconditionerForNextSolve() {}
  // The unknowns have been renumbered (the particles reordered): a kept preconditioner would
  // precondition a permuted matrix, so the next solve builds afresh whatever reuseSetup says.
  virtual void rebuildPreconditionerForNextSolve() {}
  // Whether it solves a system distributed over MPI ranks (SparseSystem.hpp): the hypre solvers.
  virtual bool distributed() const { return false; }
};

// The selection table: solvers register a factory under the name users write after `solver`.
using LinearSolverRegistry = Registry<LinearSolver, const Dictionary&, const LinearSolverControls&>;

// The solver named by `solver` in solverDict (default PCG), configured from the same
// dictionary; warns about keywords it did not use. FatalError naming the file and line for an
// unknown solver or preconditioner, for a hypre solver without MPI, or in a parallel run for a
// solver that runs on one rank only (the Eigen solvers).
std::unique_ptr<LinearSolver> makeLinearSolver(const Dictionary& solverDict,
                                               const std::string& field);

// The registered solver names (sorted).
std::vector<std::string> linearSolverNames();

}  // namespace isph
