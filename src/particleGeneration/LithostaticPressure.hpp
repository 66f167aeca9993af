#pragma once
// The initial pressure of material at rest under gravity (`initialPressure lithostatic;`):
//     p = ∫ ρ |g| ds over the material column above each particle, measured along g,
// so that a frictional material does not start without strength (numerics note §0). The
// column is the ray from the particle against g; it is cut where it crosses region
// boundaries, and each stretch takes the density of the first listed region that holds it
// (material layers of different density add up; gaps of air add nothing). Exact for the
// shapes on any lattice and tilt: a particle dx/2 below the free surface gets ρ|g|dx/2.
// Particles are independent (same result for any number of threads).
#include <vector>

#include "geometry/Region.hpp"
#include "geometry/Vec2.hpp"

namespace isph {

// `points` and `up` (the unit vector against g) in the regions' frame; `densities[r]` of
// region r; `g` = |g|. Returns p per point [Pa].
std::vector<double> lithostaticPressure(const std::vector<Vec2>& points,
                                        const std::vector<const Region*>& regions,
                                        const std::vector<double>& densities, const Vec2& up,
                                        double g);

}  // namespace isph
