#pragma once
// The plain projection (Chorin; the paper's Eqs. 10-11): the predictor sees no pressure, the
// PPE solves for p^{n+1} and Eq. 11 corrects u* with its renormalised difference gradient
// (VelocityCorrection.hpp), exact for linear fields where the support is cut. The walls'
// pressures of the step follow from u* before the correction (WallBoundary).
#include "isph/stages/Projection.hpp"

namespace isph {

class PlainProjection final : public Projection {
 public:
  explicit PlainProjection(const StageSetup& setup);
  std::string describe() const override;
  SolverPerformance solvePressure(StepContext& c, PressurePoissonEquation& ppe, const std::vector<Vec3>& ustar,
                                  double dt) override;
  void correct(StepContext& c, const std::vector<Vec3>& ustar, double dt) override;
};

}  // namespace isph
