#pragma once
// The walls' state in a step, with one writer: the boundary condition that the wall and dummy
// particles carry (WallBoundaryPressure.hpp). At the step start (prepare) each material
// particle's pull limit (its pressure pⁿ, 0 on the free surface) and the pressure gradient
// along a friction wall (its own lagged gradient for a material that slides, ρ g for one that
// sticks); once the step's pressure of the material is known (update), the wall and dummy
// particles' pressures, the Shepard mean of p_b(a), which are written and which the force on
// a wall and the Coulomb friction read. The state lives in ParticleSystem's arrays
// (wallPullLimit, wallTangentialGradient and the boundary particles' p), where the formulas
// read it; this class is what sets them.
#include <vector>

#include "core/Types.hpp"
#include "isph/ParticleSystem.hpp"

namespace isph {

class WallBoundary {
 public:
  // `slidingMaterial`: some material slides on the walls (WallFriction::slidingMaterial): only
  // then is its pressure gradient needed along them.
  WallBoundary(ParticleSystem& ps, const MaterialTable& materials, const Vec3& g, double correctionMinDeterminant,
               bool slidingMaterial);

  // The step start: pull limits and tangential gradients from the particles' state
  // (`freeSurface`: the step's flags, one per material particle at least).
  void prepare(const std::vector<char>& freeSurface);
  // The wall and dummy particles' pressures for the intermediate velocity `ustar` over `dt`.
  void update(const std::vector<Vec3>& ustar, double dt);
  // The walls' pressures of material at rest against them with velocity u* (dt = 1), before a
  // first step: the neighbours found afresh, no free surface.
  void settle(const Kernel& kernel, const std::vector<Vec3>& ustar);

 private:
  ParticleSystem& ps_;
  const MaterialTable& materials_;
  Vec3 g_;
  double minDeterminant_;
  bool slidingMaterial_;
};

}  // namespace isph
