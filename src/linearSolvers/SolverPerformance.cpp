#include "linearSolvers/SolverPerformance.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Log.hpp"

namespace isph {

std::string SolverPerformance::str() const {
  return fmt::format(
      "{}:  Solving for {}, Initial residual = {:g}, Final residual = {:g}, No Iterations {}",
      solverName, field, initialResidual, finalResidual, iterations);
}

void logSolverPerformance(const SolverPerformance& performance) {
  infoLine(performance.str());
  if (!performance.converged) {
    warning(fmt::format(
        "{}: the solve for {} did not converge (final residual {:g} after {} iterations)",
        performance.solverName, performance.field, performance.finalResidual,
        performance.iterations));
  }
}

}  // namespace isph
