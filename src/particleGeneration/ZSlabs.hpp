#pragma once
// A 3D scene's layers (Extrusion.hpp) grouped into slabs: runs of consecutive layers in which
// the same regions are present with the same sections. A region with `zRange (z0 z1)` is
// present in the layers whose z = (k + 1/2) dx lies in [z0, z1]; one without spans the width;
// a 3D region (a cylinder) is present where it has a section, and its section changes with z,
// so each layer it is present in is a slab of its own; walls span the width always. Each slab
// is then an x-y section of its own, filled and walled as a 2D scene is, and repeated over
// its layers. A 2D scene, or a 3D one whose regions all span the width, is one slab.
#include <vector>

#include "particleGeneration/Scene.hpp"

namespace isph {

struct ZSlab {
  std::vector<double> z;      // its layers, ascending
  std::vector<bool> regions;  // present, by index into Scene::regions
};

std::vector<ZSlab> zSlabs(const Scene& scene);

// The layers of `range` in `scene` (all of them when absent).
long layersIn(const Scene& scene, const std::optional<ZRange>& range);

// The x-y section of region r at layer z: the region itself (extruded) or a 3D region's cut
// (held in `cut`); null where it is absent.
const Region* sectionOf(const RegionSpec& r, double z, std::unique_ptr<Region>& cut);

}  // namespace isph
