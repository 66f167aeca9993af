#pragma once
// `viscousTerm explicit;`: Eq. 6 as the paper writes it, u* = uⁿ + dt (Σ τ pair sum/ρ + g)
// (IntermediateVelocity), then the explicit capped Coulomb friction of the walls. Its viscous
// time-step limit, dt ≤ C_ν ρ h²/η, is the solver's (TimeStepControl). Also the predictor of a
// scene whose materials have no deviatoric stress (gravity alone).
#include "isph/stages/DeviatoricTerm.hpp"

namespace isph {

class ExplicitDeviatoricTerm final : public DeviatoricTerm {
 public:
  explicit ExplicitDeviatoricTerm(const StageSetup& setup);
  bool isImplicit() const override { return false; }
  std::string describe() const override;
  double predict(StepContext& c, double dt, long stepsTaken, std::vector<Vec3>& ustar, StepReport& report) override;

 private:
  bool deviatoric_;  // some material has a deviatoric stress
};

// The explicit capped Coulomb friction on u* of the material (WallFriction::applyExplicit), and
// the walls' share of it into `wallTraction` (parallel: with the ghosts' forces). Nothing when
// no wall has friction for the scene's materials. Also the weakly-compressible method's.
void applyExplicitFriction(const WallFriction& friction, const ParticleSystem& ps, double dt, std::vector<Vec3>& ustar,
                           std::vector<Vec3>& wallTraction);

}  // namespace isph
