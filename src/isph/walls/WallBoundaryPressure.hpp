#pragma once
// The wall as the pressure sees it: a discrete Neumann condition carried by the wall and
// dummy particles. Seen from a material particle a, a boundary particle b (wall or dummy,
// with the outward normal n of its wall) holds the pressure extrapolated from a,
//
//   p_b(a) = p_a + ∇p·(x_b − x_a),  ∇p·n = ρ_a u*_a·n/dt,  ∇p·t = G_a·t,
//
// The normal part is the projection's wall condition ∂p/∂n = ρ u*·n/dt (u·n = 0 after
// Eq. 11). Towards the wall it holds in full (a wall pushes). Away from it, it would pull
// the material back with a suction that the material cannot carry where it is about to
// separate (a front lifting off the bed, a flow leaving a wall): there the drop below p_a
// is limited to ps.wallPullLimit[a], the particle's pressure at the end of the last step
// (0 on the free surface). Material in contact under pressure is held (without this, a fluid
// at rest drifts off the walls, growing by a few per cent per step); material at p = 0 is
// free to leave.
// Along the wall, G_a = ρ_a g (hydrostatic, Adami et al. 2012), except for granular material
// on a patch with friction: there the friction carries the weight along the wall, not a
// pressure gradient (on an infinite slope at rest ∂p/∂t = 0, and ρ g·t would push the bed
// row uphill), so G_a = ps.wallTangentialGradient[a], the material's own lagged pressure
// gradient (MaterialGradient). For a fluid at rest u* = g dt and p_b(a) = p_a + ρ g·(x_b − x_a):
// the hydrostatic field is exact in every direction. The same p_b(a) enters the PPE row of a (Eq. 10) and the pressure
// gradient of a (Eq. 11), so the two stay consistent.
#include <algorithm>
#include <vector>

#include "isph/ParticleSystem.hpp"

namespace isph {

// The outward normal of boundary particle b (its own for wall particles, its wall's for dummies).
inline const Vec3& wallNormal(const ParticleSystem& ps, std::size_t b) {
  return ps.isWall(b) ? ps.cloud.normal[b] : ps.cloud.normal[static_cast<std::size_t>(ps.parentWall[b])];
}

// Whether material particle a is on boundary particle b's side of its wall (in front of the
// wall line, along its outward normal). A wall particle takes pressure and friction only from
// the material in front of it: the support of a wall thinner than the kernel's (a barrier or
// a gate of two spacings) reaches through it, and the back face's particles would otherwise
// take the pressure of the material pressing on the front face (at 10.8 mm the barrier
// tutorial's 20 mm barrier read 35-85 N on its back face from the sand upstream). The
// PPE and Eq. 11 need no such test: p_b(a) is the same for a boundary particle seen from
// either side (δ_ab below is even in n).
inline bool facesMaterial(const ParticleSystem& ps, std::size_t b, std::size_t a) {
  return (ps.cloud.positions[a] - ps.cloud.positions[b]).dot(wallNormal(ps, b)) > 0;
}

// Where a particle sits as the symmetric sums of the weakly-compressible step see it: a boundary
// particle half a spacing behind its wall line, on the material's lattice continued (the wall
// particles sit on the line, half a spacing closer; there the paper's symmetric form of Eq. 11
// held a layer at rest up by about twice its weight); a material particle where it is.
inline Vec3 latticePosition(const ParticleSystem& ps, std::size_t b) {
  return ps.isMaterial(b) ? ps.cloud.positions[b] : Vec3(ps.cloud.positions[b] - 0.5 * ps.dx * wallNormal(ps, b));
}

// p_b(a) − p_a for material particle a and boundary particle b: along the normal (the pull
// limited) and along the wall.
inline double wallPressureIncrement(const ParticleSystem& ps, const std::vector<Vec3>& ustar, const Vec3& g,
                                    std::size_t a, std::size_t b, double dt) {
  const Vec3& n = wallNormal(ps, b);
  const Vec3 rba = ps.cloud.positions[b] - ps.cloud.positions[a];
  const double rn = rba.dot(n);
  const double normal = ps.rho[a] * ustar[a].dot(n) / dt * rn;  // rn < 0: pushes when moving in
  const Vec3 G = ps.frictionWall[b] ? ps.wallTangentialGradient[a] : Vec3(ps.rho[a] * g);
  return std::max(normal, -ps.wallPullLimit[a]) + G.dot(rba - rn * n);
}

// After the solve: each wall and dummy particle takes the Shepard (kernel-weighted) mean of
// p_b(a) over its material neighbours in front of it (facesMaterial), or 0 where none is near. These are the
// pressures that are written and that the force on a wall integrates.
void updateWallPressure(ParticleSystem& ps, const std::vector<Vec3>& ustar, const Vec3& g, double dt);

}  // namespace isph
