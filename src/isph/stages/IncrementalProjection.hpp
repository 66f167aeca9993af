#pragma once
// The incremental projection (`incrementalPressure granular | all;`; only with the
// semi-implicit deviatoric term): the viscous solve of u* sees the pressure force of the last
// step (`lagged()`), the PPE solves for the increment δp = p^{n+1} − pⁿ and Eq. 11 corrects
// with ∇δp (Goda 1979; van Kan 1986). The plain projection moves each particle by its own
// −dt²∇p/ρ after the viscous solve, which the deviatoric stress never resists: next to the
// free faces of a stiff block, where ∇p is not a rigid-body field, that spread a block that
// should stick along its bed at 1.5 cm/s. With it the stress resists the pressure as the
// coupled equations would, and δp → 0 in material at rest. The lagged force is in the form
// isphSchemes `laggedPressure { form pairs | gradient; smoothing N; }` names (LaggedPressure.hpp):
// by default the conservative pair form, so the pressure inside a zone moving as a rigid body
// exerts no net force on it, and the walls' pairs are exactly the normal reaction that Coulomb
// friction is limited by (WallFriction); `form gradient` uses the gradient of Eq. 11 of pⁿ
// after N Shepard passes, consistent where the support is cut (with it a collapsing column
// keeps its static wedge; with the pair form's error at the free surface the column ran off
// its floor). The first step of a fresh start is a plain one.
// Not the default: in such zones the pressure is carried from step to step and its
// distribution is statically undetermined, so it follows the history: a layer at rest on a
// slope between end walls (granularAtRest) stays put (0.85 mm) but ends with p 20 % (L2) off
// the infinite-slope lithostatic field, its end walls taking load as buttresses (16 % with
// the gradient form, a uniform excess of 7 % of ρ g H; the barrier's deposit then presses on
// the barrier with more than its along-bed weight: doc/notes/columnCollapse.md).
// Refused at their line: `pressureGradient symmetric` (the increment is corrected with the
// renormalised gradient) and, with the pair form, `wallFriction { normalForce hydrostatic; }`
// (the capacity is the pairs' reaction).
#include "isph/stages/PlainProjection.hpp"

namespace isph {

class IncrementalProjection final : public PlainProjection {
 public:
  explicit IncrementalProjection(const StageSetup& setup);
  std::string describe() const override;
  void beforePredictor(StepContext& c, double dt, bool freshStart, std::vector<Vec3>& reaction) override;
  SolverPerformance solvePressure(StepContext& c, PressurePoissonEquation& ppe, const std::vector<Vec3>& ustar,
                                  double dt) override;
  void correct(StepContext& c, const std::vector<Vec3>& ustar, double dt) override;

 private:
  bool gradientForm_ = false;     // laggedPressure { form gradient; }
  int smoothing_ = 0;             // its Shepard passes over pⁿ
  std::vector<double> increment_;  // p^{n+1} − pⁿ of the material
};

}  // namespace isph
