#pragma once
// The part of solve() that every solver shares (LinearSolver.hpp defines the residual):
// check the system, return x = 0 for b = 0, measure the warm start's residual and stop if
// it already meets the tolerance, let the concrete solver iterate towards the target
// max(tolerance, relTol * r_initial), then judge the result by our own residual. If a
// solver stops early on its own (recursive) residual estimate, it is restarted from its
// result, at most twice, within the remaining iterations. In a parallel run every rank calls
// solve() with its block of the system (SparseSystem.hpp), and the norms are global.
#include "linearSolvers/LinearSolver.hpp"

namespace isph {

class ControlledLinearSolver : public LinearSolver {
 public:
  explicit ControlledLinearSolver(LinearSolverControls controls) : controls_(std::move(controls)) {}

  SolverPerformance solve(const SparseSystem& A, std::vector<double>& x) final { return solveTo(A, x, controls_.relTol); }
  SolverPerformance solveFinal(const SparseSystem& A, std::vector<double>& x) final { return solveTo(A, x, 0.0); }
  bool stopsAtRelTol() const final { return controls_.relTol > 0; }
  int solvesDone() const final { return solves_; }
  const LinearSolverControls& controls() const { return controls_; }

 protected:
  // Improve x until ||b - A x|| / ||b|| <= target or maxIter iterations are spent; return
  // the iterations used and add the times to `performance`.
  virtual int iterate(const SparseSystem& A, std::vector<double>& x, double target, int maxIter,
                      SolverPerformance& performance) = 0;
  // ||b - A x|| / bNorm, the residual the solve is judged by (bNorm = ||b||, > 0): our own
  // CSR product on one rank. A distributed solver overrides it for a distributed system.
  virtual double residual(const SparseSystem& A, const std::vector<double>& x, double bNorm,
                          SolverPerformance& performance);
  // The solve of A is over: drop what was kept for it.
  virtual void release() {}

 private:
  SolverPerformance solveTo(const SparseSystem& A, std::vector<double>& x, double relTol);

  LinearSolverControls controls_;
  int solves_ = 0;
};

}  // namespace isph
