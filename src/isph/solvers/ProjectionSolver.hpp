#pragma once
// The paper's method (`method isph;`, the default): one ISPH projection step (Chorin; Eqs.
// 6-11) as a short list of stages over small single-purpose classes (step()):
//   findNeighbours → correctKernels (renormalisation, free surface, WallBoundary::prepare) →
//   intermediateVelocity, u* (Eq. 6) → solvePressure, the PPE (Eqs. 8/10) →
//   WallBoundary::update → correctAndMove (Eq. 11, x^{n+1}) → finishStep (shifting, safeguards)
//
// Incremental projection (isphSchemes `incrementalPressure granular|all;`, default none; only
// with the semi-implicit viscous term): the viscous solve of u* sees the pressure force of the
// last step (laggedPressureForce), the PPE solves for the increment δp = p^{n+1} − pⁿ and
// Eq. 11 corrects with ∇δp (Goda 1979; van Kan 1986). The plain projection moves each
// particle by its own −dt²∇p/ρ after the viscous solve, which the deviatoric stress never
// resists: next to the free faces of a stiff block, where ∇p is not a rigid-body field, that
// spread a block that should stick along its bed at 1.5 cm/s. With it the stress resists the
// pressure as the coupled equations would, and δp → 0 in material at rest. By default the
// lagged pressure force is the conservative pair form, so the pressure inside a zone moving
// as a rigid body exerts no net force on it, and the walls' pairs are exactly the normal
// reaction that Coulomb friction is limited by (WallFriction); `laggedPressure { form
// gradient; smoothing 3; }` uses the gradient of Eq. 11 instead, consistent where the support
// is cut (LaggedPressure.hpp: with it a collapsing column keeps its static wedge; with the
// pair form's error at the free surface the column ran off its floor). The first step of a
// fresh start is a plain one.
// Not the default: in such zones the pressure is carried from step to step and its
// distribution is statically undetermined, so it follows the history: a layer at rest on a
// slope between end walls (granularAtRest) stays put (0.85 mm) but ends with p 20 % (L2) off
// the infinite-slope lithostatic field, its end walls taking load as buttresses (16 % with
// the gradient form, a uniform excess of 7 % of ρ g H; the barrier's deposit then presses on
// the barrier with more than its along-bed weight: doc/notes/columnCollapse.md).
#include <memory>
#include <vector>

#include "isph/ImplicitViscousStep.hpp"
#include "isph/PressurePoissonEquation.hpp"
#include "isph/solvers/ParticleSolver.hpp"

namespace isph {

class ProjectionSolver final : public ParticleSolver {
 public:
  // Reads the case (ParticleSolver) and system/isphSolution (the linear solvers of p and U).
  ProjectionSolver(const Time& time, bool parallel);

  StepReport step(const Time& time) override;
  std::string preconditionerSummary() const override;

 private:
  bool explicitDeviatoricTerm() const override { return !viscous_; }
  void saveMethodState(StepState& s) const override;
  void restoreMethodState(const StepState& s) override;
  void afterWrite() override;
  std::string wallCondition() const override { return "Neumann wall pressure"; }

  // The step's neighbours; every reorderInterval-th step the material reordered along cells
  // first (parallel: ghosts, and migration on those steps).
  void findNeighbours(const Time& time);
  // The kernel gradient correction, the free surface and the walls' state at the step start.
  void correctKernels(StepReport& report);
  // The PPE (Eq. 10) for p^{n+1}, or for its increment in the incremental projection.
  void solvePressure(double dt, StepReport& report);
  // u* of Eq. 6: the deviatoric term (semi-implicit or explicit), gravity, the wall friction
  // and, in the incremental projection, the lagged pressure force.
  void intermediateVelocity(const Time& time, StepReport& report);
  // −∇pⁿ/ρ of the incremental projection into lagged_ (the walls' reaction for the friction
  // into `reaction` with the pair form).
  void laggedPressure(double dt, std::vector<Vec3>& reaction);
  // Eq. 11 (or its increment form), then x^{n+1} with the mean of uⁿ and u^{n+1}.
  void correctAndMove(double dt);
  // The incremental projection in this step: not in the first step of a fresh start, which
  // finds the pressure that it carries.
  bool incrementalNow() const { return incremental_ && viscous_ && !(freshStart_ && stepsTaken_ <= 1); }

  std::unique_ptr<PressurePoissonEquation> ppe_;
  std::unique_ptr<ImplicitViscousStep> viscous_;  // the semi-implicit deviatoric term (null: explicit)
  std::vector<Vec3> lagged_;        // −∇pⁿ/ρ of the incremental projection (empty: off)
  std::vector<double> increment_;   // p^{n+1} − pⁿ of the material (incremental projection)
  bool incremental_ = false;        // incremental projection active
  std::vector<scalar> pStart_;      // p at the step start (restored when a solve fails)
};

}  // namespace isph
