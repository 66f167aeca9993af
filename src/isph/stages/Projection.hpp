#pragma once
// The projection of the step: what pressure force the predictor (Eq. 6) sees, the PPE
// (Eq. 10) and the velocity correction (Eq. 11), a stage chosen by name from isphSchemes'
// `incrementalPressure none | granular | all` and the scene:
//   plain        PlainProjection: the PPE for p^{n+1}, Eq. 11 with the whole pressure
//                (Chorin; the paper's method; `incrementalPressure none`, the default)
//   incremental  IncrementalProjection: the predictor sees the pressure force of the last
//                step, the PPE solves for the increment (`granular`: in a scene with a
//                granular material; `all`: in every scene with the semi-implicit deviatoric
//                term)
// The material velocities and the walls' pressures of the step are its result; the particles
// move afterwards (the solver).
#include <memory>
#include <string>
#include <vector>

#include "core/Registry.hpp"
#include "isph/PressurePoissonEquation.hpp"
#include "isph/stages/DeviatoricTerm.hpp"
#include "isph/stages/StepContext.hpp"

namespace isph {

class Projection {
 public:
  // The projection the entries and the scene select. Refuses, at the entry's line, the
  // incremental projection with the explicit deviatoric term (it needs the semi-implicit
  // solve) and `laggedPressure` without the incremental projection.
  static std::unique_ptr<Projection> New(const StageSetup& setup, const DeviatoricTerm& deviatoric);
  virtual ~Projection() = default;

  // Its lines for the log's list of schemes.
  virtual std::string describe() const = 0;
  // Before the predictor: the pressure force per unit mass it sees (lagged(); empty: none)
  // and, where the walls' normal reaction comes from that force, the friction walls' reaction
  // on each material particle into `reaction` (left empty: WallFriction takes the wall
  // pressures). `freshStart`: the first step of a run from particleMesh's fields, which has
  // no pressure to lag.
  virtual void beforePredictor(StepContext& c, double dt, bool freshStart, std::vector<Vec3>& reaction);
  const std::vector<Vec3>& lagged() const { return lagged_; }
  // The PPE of the step (Eq. 10): the material's p^{n+1} into ps.cloud.p.
  virtual SolverPerformance solvePressure(StepContext& c, PressurePoissonEquation& ppe, const std::vector<Vec3>& ustar,
                                          double dt) = 0;
  // Eq. 11: the material's u^{n+1} into ps.cloud.U (with the ghosts'), and the walls'
  // pressures of the step (WallBoundary::update).
  virtual void correct(StepContext& c, const std::vector<Vec3>& ustar, double dt) = 0;

 protected:
  std::vector<Vec3> lagged_;  // −∇pⁿ/ρ the predictor sees (empty: none)
};

using ProjectionRegistry = Registry<Projection, const StageSetup&>;

}  // namespace isph
