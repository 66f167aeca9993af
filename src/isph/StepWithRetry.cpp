#include "isph/StepWithRetry.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

namespace {

std::string attempt(const std::string& timeName, double dt, const SolverPerformance& ppe) {
  return fmt::format("time {} (deltaT {:.4g}): {} residual {:.3g} after {} iterations", timeName, dt,
                     ppe.solverName, ppe.finalResidual, ppe.iterations);
}

}  // namespace

StepReport stepWithRetry(Time& time, const std::function<StepReport(const Time&)>& step) {
  const StepReport first = step(time);
  if (first.ppe.converged) return first;

  const double failedDeltaT = time.deltaT();
  const std::string failed = attempt(time.timeName(), failedDeltaT, first.ppe);
  time.redoStep(0.5 * failedDeltaT);
  warning(fmt::format("the pressure Poisson equation did not converge at {};\n    retrying the step once with "
                      "half the step: time {}, deltaT {:.4g}",
                      failed, time.timeName(), time.deltaT()));
  const StepReport retry = step(time);
  if (!retry.ppe.converged) {
    fatalError(fmt::format(
        "the pressure Poisson equation (field {}) did not converge, after one retry with a smaller step:\n"
        "    first attempt: {}\n    retry:         {}\n"
        "    The last written time directory is intact; try a smaller maxCo or maxDeltaT in system/controlDict, "
        "or more maxIter or a looser tolerance for p in system/isphSolution.",
        retry.ppe.field.empty() ? "p" : retry.ppe.field, failed,
        attempt(time.timeName(), time.deltaT(), retry.ppe)));
  }
  if (!time.settings().adjustTimeStep) time.setDeltaT(failedDeltaT);
  return retry;
}

}  // namespace isph
