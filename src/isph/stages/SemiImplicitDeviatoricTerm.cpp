#include "isph/stages/SemiImplicitDeviatoricTerm.hpp"

#include <fmt/format.h>

#include <chrono>

#include "isph/parallel/GhostExchange.hpp"

namespace isph {

namespace {

const bool registered = DeviatoricTermRegistry::add(
    "implicit", [](const StageSetup& setup) { return std::make_unique<SemiImplicitDeviatoricTerm>(setup); });

}  // namespace

SemiImplicitDeviatoricTerm::SemiImplicitDeviatoricTerm(const StageSetup& setup)
    : viscous_(std::make_unique<ImplicitViscousStep>(setup.solution.subDictOrEmpty("U"), setup.dimension,
                                                     setup.common.frictionPasses)),
      passes_(setup.common.frictionPasses) {}

std::string SemiImplicitDeviatoricTerm::describe() const {
  return fmt::format("    deviatoric term: semi-implicit (Morris operator, one PCG solve per component, or one for "
                     "all components where a Coulomb wall drag acts, repeated up to {} times until the stick/slip "
                     "state of every particle on a wall settles; no viscous time-step limit)\n",
                     passes_);
}

double SemiImplicitDeviatoricTerm::predict(StepContext& c, double dt, long stepsTaken, std::vector<Vec3>& ustar,
                                           StepReport& report) {
  const auto start = std::chrono::steady_clock::now();
  const auto perf = viscous_->solve(c.ps, c.materials, c.viscousStress.eta(), &c.friction, c.g, dt, c.kernel.h(),
                                    ustar);
  exchangeGhosts(c.ps, ustar);  // parallel: solved for the own particles
  report.viscous.insert(report.viscous.end(), perf.begin(), perf.end());
  // The solve's time by part; what is in none of them (the stick/slip states classified after
  // each pass, the warm start, the ghosts) and the friction's traction below: "viscous stick/slip and friction".
  double accounted = viscous_->assemblySeconds();
  c.timer.add("viscous assembly", viscous_->assemblySeconds());
  for (const auto& p : perf) {
    c.timer.add("viscous assembly", p.assemblySeconds);
    c.timer.add("viscous setup", p.setupSeconds);
    c.timer.add("viscous solve", p.solveSeconds);
    c.timer.add("viscous checks", p.checkSeconds);
    accounted += p.seconds();
  }
  if (c.friction.active()) {
    std::vector<Vec3> force = viscous_->frictionForce();
    if (!force.empty()) {  // parallel: solved for the own rows
      force.resize(c.ps.nMaterial, Vec3::Zero());
      exchangeGhosts(c.ps, force);
    }
    c.wallFriction = c.friction.wallTraction(c.ps, force);
  }
  c.timer.add("viscous stick/slip and friction", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - accounted);
  auto t = c.timer.scope("rheology");
  c.viscousStress.keepActing(&ustar, stepsTaken);  // u* with its ghosts (exchanged above)
  return 0;
}

std::string SemiImplicitDeviatoricTerm::summary() const {
  std::string s = fmt::format("AMG hierarchies built for U: {} of {} solves", viscous_->preconditionersBuilt(),
                              viscous_->solvesDone());
  if (viscous_->frictionSolves() > 0) {
    s += fmt::format("\nBed friction: stick/slip states settled in {} of {} steps ({:.2f} passes per step, at most {})",
                     viscous_->frictionSolvesSettled(), viscous_->frictionSolves(),
                     static_cast<double>(viscous_->frictionPassesDone()) / viscous_->frictionSolves(),
                     viscous_->maxFrictionPasses());
  }
  return s;
}

}  // namespace isph
