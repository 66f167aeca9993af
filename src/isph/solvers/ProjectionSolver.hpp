#pragma once
// The paper's method (`method isph;`, the default): one ISPH projection step (Chorin; Eqs.
// 6-11) as a short list of stages over small single-purpose classes (step()):
//   findNeighbours → correctKernels (renormalisation, free surface, WallBoundary::prepare) →
//   intermediateVelocity, u* (Eq. 6; the deviatoric term a stage: stages/DeviatoricTerm.hpp)
//   → the PPE (Eqs. 8/10) → Eq. 11 and the walls' pressures (the projection a stage:
//   stages/Projection.hpp) → x^{n+1} → finishStep (shifting, safeguards)
// The stages are chosen by name from system/isphSchemes (viscousTerm; the projection is the
// plain one), each reading its own entries; the solver owns the particles and the models they
// share.
#include <memory>
#include <vector>

#include "isph/pressure/PressurePoissonEquation.hpp"
#include "isph/solvers/ParticleSolver.hpp"
#include "isph/stages/DeviatoricTerm.hpp"
#include "isph/stages/Projection.hpp"

namespace isph {

class ProjectionSolver final : public ParticleSolver {
 public:
  // Reads the case (ParticleSolver) and system/isphSolution (the linear solvers of p and U).
  ProjectionSolver(const Time& time, bool parallel);

  StepReport step(const Time& time) override;
  std::string preconditionerSummary() const override;

 private:
  bool explicitDeviatoricTerm() const override { return !deviatoric_->isImplicit(); }
  void saveMethodState(StepState& s) const override { deviatoric_->saveState(s); }
  void restoreMethodState(const StepState& s) override { deviatoric_->restoreState(s); }
  void afterWrite() override;
  std::string wallCondition() const override { return "Neumann wall pressure"; }
  std::string describeStages() const override { return deviatoric_->describe() + projection_->describe(); }

  // The step's neighbours; every reorderInterval-th step the material reordered along cells
  // first (parallel: ghosts, and migration on those steps).
  void findNeighbours(const Time& time);
  // The kernel gradient correction, the free surface and the walls' state at the step start.
  void correctKernels(StepReport& report);
  // u* of Eq. 6: the viscosities, the pressure force the projection lags, the wall friction
  // and the deviatoric term.
  void intermediateVelocity(const Time& time, StepReport& report);
  // The PPE (Eq. 10) of the projection, with its phases' times.
  void solvePressure(double dt, StepReport& report);
  // Eq. 11 of the projection, then x^{n+1} with the mean of uⁿ and u^{n+1}.
  void correctAndMove(double dt);

  StepContext context_;  // the particles and models the stages work on
  std::unique_ptr<PressurePoissonEquation> ppe_;
  std::unique_ptr<DeviatoricTerm> deviatoric_;
  std::unique_ptr<Projection> projection_;
  std::vector<scalar> pStart_;  // p at the step start (restored when a solve fails)
};

}  // namespace isph
