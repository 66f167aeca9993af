#pragma once
// The projection of the step: the PPE (Eq. 10) and the velocity correction (Eq. 11), a stage
// chosen by name from the registry (one today: PlainProjection, Chorin's projection as the
// paper writes it). Issue 48 measured two incremental forms against it (the predictor seeing
// the last pressure force; doc/notes/granularStep.md); neither passed, so the plain projection
// is the one projection of every scene.
// The material velocities and the walls' pressures of the step are its result; the particles
// move afterwards (the solver).
#include <memory>
#include <string>
#include <vector>

#include "core/Registry.hpp"
#include "isph/pressure/PressurePoissonEquation.hpp"
#include "isph/stages/StepContext.hpp"

namespace isph {

class Projection {
 public:
  // The projection of the case ("plain").
  static std::unique_ptr<Projection> New(const StageSetup& setup);
  virtual ~Projection() = default;

  // Its lines for the log's list of schemes.
  virtual std::string describe() const = 0;
  // The PPE of the step (Eq. 10): the material's p^{n+1} into ps.cloud.p.
  virtual SolverPerformance solvePressure(StepContext& c, PressurePoissonEquation& ppe, const std::vector<Vec3>& ustar,
                                          double dt) = 0;
  // Eq. 11: the material's u^{n+1} into ps.cloud.U (with the ghosts'), and the walls'
  // pressures of the step (WallBoundary::update).
  virtual void correct(StepContext& c, const std::vector<Vec3>& ustar, double dt) = 0;
};

using ProjectionRegistry = Registry<Projection, const StageSetup&>;

}  // namespace isph
