#include "isph/stages/IncrementalProjection.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/dictionary/RequireRange.hpp"
#include "isph/LaggedPressure.hpp"
#include "isph/VelocityCorrection.hpp"
#include "isph/parallel/GhostExchange.hpp"

namespace isph {

namespace {

const bool registered = ProjectionRegistry::add(
    "incremental", [](const StageSetup& setup) { return std::make_unique<IncrementalProjection>(setup); });

}  // namespace

IncrementalProjection::IncrementalProjection(const StageSetup& setup) : PlainProjection(setup) {
  const Dictionary& d = setup.schemes;
  if (symmetric_) {
    fatalIOError(d.findEntry("pressureGradient")->location(),
                 fmt::format("keyword 'pressureGradient' in {}: the incremental projection (incrementalPressure, "
                             "acting in this scene) corrects with the renormalised gradient of the increment; the "
                             "symmetric form would not be used: remove one of the two",
                             d.name()));
  }
  const Dictionary lp = d.subDictOrEmpty("laggedPressure");
  gradientForm_ = lp.getChoiceOrDefault("form", {"pairs", "gradient"}, "pairs") == "gradient";
  smoothing_ = lp.getOrDefault("smoothing", smoothing_);
  requireRange(lp, "smoothing", smoothing_, 0, 10);
  if (!gradientForm_ && smoothing_ > 0) {
    fatalIOError(lp.findEntry("smoothing")->location(),
                 fmt::format("keyword 'smoothing' in {}: the pair form uses pⁿ as it is; smoothing needs "
                             "'form gradient'",
                             lp.name()));
  }
  lp.checkKeywords();
  if (!gradientForm_ && setup.common.frictionNormal == FrictionNormal::hydrostatic) {
    const Dictionary wf = d.subDictOrEmpty("wallFriction");
    fatalIOError(wf.findEntry("normalForce")->location(),
                 fmt::format("keyword 'normalForce' in {}: with the incremental projection's pair form "
                             "(laggedPressure {{ form pairs; }}) the Coulomb capacity is the wall pairs' normal "
                             "reaction; normalForce hydrostatic is not used: remove it or use laggedPressure {{ form "
                             "gradient; }}",
                             wf.name()));
  }
}

std::string IncrementalProjection::describe() const {
  return "    projection: incremental (the viscous solve sees the last pressure force; the PPE solves for the "
         "increment, Eq. 11 corrects with its renormalised gradient)\n" +
         (gradientForm_
              ? fmt::format("    lagged pressure force: the renormalised gradient of Eq. 11 of p^n{}; Coulomb friction "
                            "from the wall pressures\n",
                            smoothing_ > 0
                                ? fmt::format(" after {} Shepard pass{}", smoothing_, smoothing_ > 1 ? "es" : "")
                                : std::string())
              : std::string("    lagged pressure force: symmetric pair form; the friction walls' pairs give the "
                            "normal reaction for the Coulomb friction\n"));
}

void IncrementalProjection::beforePredictor(StepContext& c, double dt, bool freshStart, std::vector<Vec3>& reaction) {
  if (freshStart) {  // no pressure to lag yet: a plain step
    lagged_.clear();
    return;
  }
  // −∇pⁿ/ρ with the walls' condition of a material at rest, ũ = uⁿ + dt g.
  ParticleSystem& ps = c.ps;
  lagged_.resize(ps.nMaterial);
  std::vector<Vec3> resting(ps.cloud.U);
  for (std::size_t a = 0; a < ps.nMaterial; ++a) resting[a] += dt * c.g;
  const long n = static_cast<long>(ps.nMaterial);
  if (gradientForm_) {
    // The gradient of Eq. 11 of p̃ (LaggedPressure.hpp); the PPE then solves for p^{n+1} − p̃.
    if (smoothing_ > 0) {
      const std::vector<double> smooth = smoothedPressure(ps, c.kernel, c.freeSurface.flags(), smoothing_);
      std::copy(smooth.begin(), smooth.end(), ps.cloud.p.begin());
    }
#pragma omp parallel for schedule(static)
    for (long ia = 0; ia < n; ++ia) {
      const auto a = static_cast<std::size_t>(ia);
      lagged_[a] = -pressureGradient(ps, c.correction, resting, c.g, a, dt) / ps.rho[a];
    }
  } else {
    reaction.assign(ps.nMaterial, Vec3::Zero());
#pragma omp parallel for schedule(static)
    for (long ia = 0; ia < n; ++ia) {
      const auto a = static_cast<std::size_t>(ia);
      lagged_[a] = laggedPressureForce(ps, c.kernel, resting, c.g, a, dt, &reaction[a]);
    }
  }
  exchangeGhosts(ps, lagged_);  // parallel: the walls' pressure reads it at ghosts
}

SolverPerformance IncrementalProjection::solvePressure(StepContext& c, PressurePoissonEquation& ppe,
                                                       const std::vector<Vec3>& ustar, double dt) {
  if (lagged_.empty()) return PlainProjection::solvePressure(c, ppe, ustar, dt);
  // The increment that the step applies to the predictor that saw pⁿ.
  return ppe.solveIncrement(c.ps, c.kernel, c.correction, ustar, c.freeSurface.flags(), c.g, dt, increment_);
}

void IncrementalProjection::correct(StepContext& c, const std::vector<Vec3>& ustar, double dt) {
  if (lagged_.empty()) return PlainProjection::correct(c, ustar, dt);
  correctVelocityIncrement(c.ps, c.correction, ustar, increment_, dt);
  exchangeGhosts(c.ps, c.ps.cloud.U);  // parallel
  std::vector<Vec3> ustarTotal(ustar);  // the walls' pressure from the whole condition
  for (std::size_t a = 0; a < c.ps.nMaterial; ++a) ustarTotal[a] -= dt * lagged_[a];
  c.walls.update(ustarTotal, dt);
}

}  // namespace isph
