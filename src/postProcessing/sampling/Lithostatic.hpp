#pragma once
// How far a granular layer at rest is from the infinite-slope (lithostatic) state: the
// pressure p = rho |g| cos(beta) depth, with depth measured along the bed normal from the
// highest material particle centre and |g| cos(beta) = -g . normal (the component of gravity
// into the bed), as tests/isph/GranularAtRestTest.cpp measures it:
//   - l2: sqrt(sum (p - p_lith)^2 / sum p_lith^2) over all material particles;
//   - spread: max - min of (p - p_lith) / (rho |g| H) over the interior, the material
//     particles with xMin < x < xMax (along the bed, away from the end walls) and deeper than
//     minDepth (away from the free surface);
//   - the largest displacement of a material particle from a reference cloud (matched by id).
#include "core/Types.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

struct LithostaticSpec {
  double rho = 0.0;                // [kg/m^3], > 0
  Vec3 g = Vec3(0, -9.81, 0);      // gravity [m/s^2]
  Vec3 normal = Vec3::UnitY();     // the bed normal, pointing out of the layer (normalised here)
  double xMin = -1e300, xMax = 1e300;  // the interior along x [m]
  double minDepth = 0.0;           // the interior: deeper than this [m]
  double height = 0.0;             // H of the spread's scale rho |g| H [m], > 0
};

struct LithostaticError {
  double l2 = 0.0;         // relative L2 error of p
  double spread = 0.0;     // max - min of (p - p_lith)/(rho |g| H) in the interior
  std::size_t interior = 0;  // material particles in the interior
  double surface = 0.0;    // the highest material particle centre along the normal [m]
};

// FatalError when rho or height is not positive, the normal is zero, gravity does not point
// into the bed, the cloud has no material particle or the interior holds none.
LithostaticError lithostaticError(const ParticleCloud& cloud, const LithostaticSpec& spec);

// The largest distance a material particle of `end` has moved from its place in `start`
// (matched by origId); FatalError naming the id when a particle of `end` is not in `start`.
double largestDisplacement(const ParticleCloud& start, const ParticleCloud& end);

}  // namespace isph
