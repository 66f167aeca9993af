#include "linearSolvers/ControlledLinearSolver.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Error.hpp"

namespace isph {

SolverPerformance ControlledLinearSolver::solveTo(const SparseSystem& A, std::vector<double>& x, double relTol) {
  checkSparseSystem(A);
  const auto n = static_cast<std::size_t>(A.nRows());
  if (x.empty()) x.assign(n, 0.0);
  if (x.size() != n) {
    fatalError(fmt::format("{}: solving for {} with {} rows but an initial guess of {} values",
                           name(), controls_.field, n, x.size()));
  }

  ++solves_;
  SolverPerformance perf;
  perf.solverName = name();
  perf.field = controls_.field;
  if (norm2(A.rhs) == 0.0) {  // b = 0: the solution is x = 0
    std::fill(x.begin(), x.end(), 0.0);
    perf.converged = true;
    return perf;
  }

  perf.initialResidual = normalisedResidual(A, x);
  const double target = std::max(controls_.tolerance, relTol * perf.initialResidual);
  perf.finalResidual = perf.initialResidual;
  perf.converged = perf.initialResidual <= target;

  constexpr int maxRestarts = 2;
  for (int pass = 0; !perf.converged && pass <= maxRestarts && perf.iterations < controls_.maxIter;
       ++pass) {
    const int used = iterate(A, x, target, controls_.maxIter - perf.iterations, perf);
    perf.iterations += used;
    perf.finalResidual = normalisedResidual(A, x);
    perf.converged = perf.finalResidual <= target;  // false for NaN
    if (used == 0) break;                           // no progress: restarting would not help
  }
  return perf;
}

}  // namespace isph
