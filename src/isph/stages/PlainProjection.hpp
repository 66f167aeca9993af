#pragma once
// The plain projection (Chorin; the paper's Eqs. 10-11; `incrementalPressure none;`, the
// default): the predictor sees no pressure, the PPE solves for p^{n+1} and Eq. 11 corrects u*
// with its gradient, in the form isphSchemes `pressureGradient` names (VelocityCorrection.hpp):
//   renormalised  L_a Σ V_b (p_b − p_a)∇W, exact for linear fields where the support is cut
//                 (the default)
//   symmetric     Σ m_b (p_a/ρ_a² + p_b/ρ_b²)∇W as the paper prints it; its pairs repel under
//                 pressure (granularSlope)
// The walls' pressures of the step follow from u* before the correction (WallBoundary).
#include "isph/stages/Projection.hpp"

namespace isph {

class PlainProjection : public Projection {
 public:
  explicit PlainProjection(const StageSetup& setup);
  std::string describe() const override;
  SolverPerformance solvePressure(StepContext& c, PressurePoissonEquation& ppe, const std::vector<Vec3>& ustar,
                                  double dt) override;
  void correct(StepContext& c, const std::vector<Vec3>& ustar, double dt) override;

 protected:
  bool symmetric_ = false;  // pressureGradient symmetric
};

}  // namespace isph
