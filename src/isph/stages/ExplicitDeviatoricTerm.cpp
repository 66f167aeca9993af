#include "isph/stages/ExplicitDeviatoricTerm.hpp"

#include "isph/deviatoric/IntermediateVelocity.hpp"
#include "isph/parallel/GhostExchange.hpp"

namespace isph {

namespace {

const bool registered = DeviatoricTermRegistry::add(
    "explicit", [](const StageSetup& setup) { return std::make_unique<ExplicitDeviatoricTerm>(setup); });

}  // namespace

ExplicitDeviatoricTerm::ExplicitDeviatoricTerm(const StageSetup& setup)
    : deviatoric_(setup.materials.anyDeviatoricStress()) {}

std::string ExplicitDeviatoricTerm::describe() const {
  return deviatoric_ ? "    deviatoric term: explicit (Morris operator; viscous time-step limit)\n"
                     : "    deviatoric term: none in this scene (u* from gravity alone)\n";
}

double ExplicitDeviatoricTerm::predict(StepContext& c, double dt, long stepsTaken, std::vector<Vec3>& ustar,
                                       StepReport&) {
  auto t = c.timer.scope("intermediate velocity");
  c.viscousStress.keepActing(nullptr, stepsTaken);
  const double maxAcceleration =
      IntermediateVelocity::compute(c.ps, c.materials, c.viscousStress.eta(), c.g, dt, c.kernel.h(), ustar);
  applyExplicitFriction(c.friction, c.ps, dt, ustar, c.wallFriction);
  exchangeGhosts(c.ps, ustar);  // parallel
  return maxAcceleration;
}

void applyExplicitFriction(const WallFriction& friction, const ParticleSystem& ps, double dt, std::vector<Vec3>& ustar,
                           std::vector<Vec3>& wallTraction) {
  if (!friction.active()) return;
  std::vector<Vec3> applied;
  friction.applyExplicit(ps, dt, ustar, &applied);
  exchangeGhosts(ps, applied);  // parallel
  wallTraction = friction.wallTraction(ps, applied);
}

}  // namespace isph
