#include "linearSolvers/ControlledLinearSolver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

double ControlledLinearSolver::residual(const SparseSystem& A, const std::vector<double>& x, double bNorm,
                                       SolverPerformance&) {
  return residualNorm(A, x) / bNorm;
}

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SolverPerformance ControlledLinearSolver::solveTo(const SparseSystem& A, std::vector<double>& x, double relTol) {
  release();  // (nothing may survive from a solve that ended in an error)
  const auto checkStart = std::chrono::steady_clock::now();
  const bool distributed = distributedRun();
  if (distributed) {
    checkDistributedSparseSystem(A);
  } else {
    checkSparseSystem(A);
  }
  const auto n = static_cast<std::size_t>(A.nRows());
  if (x.empty()) x.assign(n, 0.0);
  if (x.size() != n) {
    fatalError(fmt::format("{}: solving for {} with {} rows but an initial guess of {} values",
                           name(), controls_.field, n, x.size()));
  }

  ++solves_;
  SolverPerformance perf;
  perf.checkSeconds = secondsSince(checkStart);
  perf.solverName = name();
  perf.field = controls_.field;
  double bNorm = norm2(A.rhs);
  if (distributed) bNorm = std::sqrt(sumOverRanks(bNorm * bNorm));
  if (bNorm == 0.0) {  // b = 0: the solution is x = 0
    std::fill(x.begin(), x.end(), 0.0);
    perf.converged = true;
    return perf;
  }
  bNorm = std::max(bNorm, std::numeric_limits<double>::min());

  // Our residual, timed as checking (less a hand-over to the solver it may do first: assembly).
  const auto checkedResidual = [&] {
    const auto start = std::chrono::steady_clock::now();
    const double assembly = perf.assemblySeconds;
    const double r = residual(A, x, bNorm, perf);
    perf.checkSeconds += secondsSince(start) - (perf.assemblySeconds - assembly);
    return r;
  };
  perf.initialResidual = checkedResidual();
  const double target = std::max(controls_.tolerance, relTol * perf.initialResidual);
  perf.finalResidual = perf.initialResidual;
  perf.converged = perf.initialResidual <= target;

  constexpr int maxRestarts = 2;
  for (int pass = 0; !perf.converged && pass <= maxRestarts && perf.iterations < controls_.maxIter;
       ++pass) {
    const int used = iterate(A, x, target, controls_.maxIter - perf.iterations, perf);
    perf.iterations += used;
    perf.finalResidual = checkedResidual();
    perf.converged = perf.finalResidual <= target;  // false for NaN
    if (used == 0) break;                           // no progress: restarting would not help
  }
  release();
  return perf;
}

}  // namespace isph
