#pragma once
// Fills the material regions with lattice sites. Where regions overlap, the first listed
// wins: a site inside an earlier region is not given to a later one, and the later region
// counts it as lost (per earlier region, for the log). Sites come in row order (rows of
// increasing y, each of increasing x), the same for any number of threads.
#include <vector>

#include "geometry/Region.hpp"
#include "particleGeneration/Lattice.hpp"

namespace isph {

struct RegionSites {
  std::vector<Vec2> sites;   // the sites this region keeps
  long inside = 0;           // sites inside the region (kept + lost)
  std::vector<long> lostTo;  // lostTo[q]: sites inside region q listed earlier
};

std::vector<RegionSites> fillRegions(const std::vector<const Region*>& regions,
                                     const Lattice& lattice);

}  // namespace isph
