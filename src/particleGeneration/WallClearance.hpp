#pragma once
// Removes the material sites that a wall blocks: those inside a solid (behind a wall's
// surface, not past the end of a polyline) and those closer than `clearance` (dx/2 by
// default) to a wall surface, where they would sit on top of the wall particles. Keeps the
// order of the others.
#include <vector>

#include "particleGeneration/WallSurface.hpp"

namespace isph {

struct ClearanceCount {
  long inSolid = 0;
  long nearWall = 0;
};

// `walls` oriented with the material on their left (WallOrientation.hpp). `nearestSurface`
// receives, for each kept site, its distance to the nearest wall surface (capped at `cap`).
ClearanceCount removeBlockedSites(std::vector<Vec2>& sites, const std::vector<WallSurface>& walls,
                                  double clearance, std::vector<double>& nearestSurface,
                                  double cap);

}  // namespace isph
