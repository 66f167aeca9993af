#pragma once
// `viscousTerm implicit;` (the default): the deviatoric term of Eq. 6 solved semi-implicitly
// with the viscosities of the step start, (I − dt/ρ ∇·2ηⁿD) u* = uⁿ + dt g, one PCG
// solve per component, or one for all components where a Coulomb wall drag acts, repeated up
// to wallFriction's `passes` times until the stick/slip state of each particle on a wall
// settles (ImplicitViscousStep; linear solver: isphSolution's `U`). No viscous time-step limit:
// the plastic regularisation cap sets no step.
#include <memory>

#include "isph/deviatoric/ImplicitViscousStep.hpp"
#include "isph/stages/DeviatoricTerm.hpp"

namespace isph {

class SemiImplicitDeviatoricTerm final : public DeviatoricTerm {
 public:
  explicit SemiImplicitDeviatoricTerm(const StageSetup& setup);
  bool isImplicit() const override { return true; }
  std::string describe() const override;
  double predict(StepContext& c, double dt, long stepsTaken, std::vector<Vec3>& ustar, StepReport& report) override;
  void renumbered() override { viscous_->renumbered(); }
  void saveState(StepState& s) const override { viscous_->saveState(s); }
  void restoreState(const StepState& s) override { viscous_->restoreState(s); }
  std::string summary() const override;

 private:
  std::unique_ptr<ImplicitViscousStep> viscous_;
  int passes_;
};

}  // namespace isph
