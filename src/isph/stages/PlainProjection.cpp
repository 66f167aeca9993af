#include "isph/stages/PlainProjection.hpp"

#include "isph/pressure/VelocityCorrection.hpp"
#include "isph/parallel/GhostExchange.hpp"

namespace isph {

namespace {

const bool registered =
    ProjectionRegistry::add("plain", [](const StageSetup& setup) { return std::make_unique<PlainProjection>(setup); });

}  // namespace

PlainProjection::PlainProjection(const StageSetup&) {}

std::string PlainProjection::describe() const {
  return "    projection: plain (Eq. 11 corrects with the whole pressure), its gradient renormalised\n";
}

SolverPerformance PlainProjection::solvePressure(StepContext& c, PressurePoissonEquation& ppe,
                                                 const std::vector<Vec3>& ustar, double dt) {
  return ppe.solve(c.ps, c.kernel, c.correction, ustar, c.freeSurface.flags(), c.g, dt);
}

void PlainProjection::correct(StepContext& c, const std::vector<Vec3>& ustar, double dt) {
  c.walls.update(ustar, dt);  // the walls' pressures of the step (p^{n+1})
  correctVelocity(c.ps, c.correction, ustar, c.g, dt);
  exchangeGhosts(c.ps, c.ps.cloud.U);  // parallel
}

}  // namespace isph
