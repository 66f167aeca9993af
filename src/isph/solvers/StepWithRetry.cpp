#include "isph/solvers/StepWithRetry.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

namespace {

std::string attempt(const std::string& timeName, double dt, const SolverPerformance& solve) {
  return fmt::format("time {} (deltaT {:.4g}): {} residual {:.3g} after {} iterations", timeName, dt,
                     solve.solverName, solve.finalResidual, solve.iterations);
}

// What the failed solve is, in words, by its field: the PPE (p) or the implicit viscous step.
std::string what(const SolverPerformance& solve) {
  const std::string field = solve.field.empty() ? "p" : solve.field;
  return field == "p" ? "the pressure Poisson equation (field p)"
                      : fmt::format("the implicit viscous step (field {})", field);
}

}  // namespace

StepReport stepWithRetry(Time& time, const std::function<StepReport(const Time&)>& step) {
  const StepReport first = step(time);
  const SolverPerformance* firstFailure = first.failedSolve();
  if (!firstFailure) return first;

  const double failedDeltaT = time.deltaT();
  const std::string failed = attempt(time.timeName(), failedDeltaT, *firstFailure);
  const std::string failedWhat = what(*firstFailure);
  time.redoStep(0.5 * failedDeltaT);
  warning(fmt::format("{} did not converge at {};\n    retrying the step once with half the step: time {}, deltaT {:.4g}",
                      failedWhat, failed, time.timeName(), time.deltaT()));
  const StepReport retry = step(time);
  if (const SolverPerformance* again = retry.failedSolve()) {
    const bool viscous = again->field != "p" && !again->field.empty();
    fatalError(fmt::format(
        "{} did not converge, after one retry with a smaller step:\n"
        "    first attempt: {} ({})\n    retry:         {}\n"
        "    The last written time directory is intact; try a smaller maxCo or maxDeltaT in system/controlDict, "
        "or more maxIter or {} in system/isphSolution.",
        what(*again), failed, failedWhat, attempt(time.timeName(), time.deltaT(), *again),
        viscous ? fmt::format("another preconditioner for {} (or a smaller etaMax in constant/materialProperties)",
                              again->field)
                : "a looser tolerance for p"));
  }
  if (!time.settings().adjustTimeStep) time.setDeltaT(failedDeltaT);
  return retry;
}

}  // namespace isph
