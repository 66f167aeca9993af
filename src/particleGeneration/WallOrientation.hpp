#pragma once
// Puts the material on the LEFT of every wall chain, as WallLayers expects. Closed walls are
// oriented when read. An open polyline follows its `materialSide`: left keeps the chain,
// right reverses it, auto probes the material regions on both sides of the polyline, at
// points dx apart along it and (k + 1/2) dx from it out to `reach`, and takes the side where
// more probes fall in material (a FatalIOError at the wall's entry when none does: the user
// must then say).
#include <vector>

#include "particleGeneration/Scene.hpp"

namespace isph {

struct WallSide {
  bool reversed = false;
  long probesLeft = 0, probesRight = 0;  // auto: probes in material, as given (before reversing)
  bool automatic = false;
};

std::vector<WallSurface> orientWalls(const std::vector<WallSpec>& walls,
                                     const std::vector<const Region*>& material, double dx,
                                     double reach, std::vector<WallSide>& sides);

}  // namespace isph
