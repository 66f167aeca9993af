#include "particleGeneration/ZSlabs.hpp"

#include "particleGeneration/Extrusion.hpp"

namespace isph {

namespace {

bool present(const std::optional<ZRange>& range, double z) { return !range || range->contains(z); }

}  // namespace

std::vector<ZSlab> zSlabs(const Scene& scene) {
  std::vector<ZSlab> slabs;
  for (const double z : extrusionLayers(scene)) {
    std::vector<bool> regions;
    bool cut = false;  // a 3D region's section here: a slab of one layer
    for (const RegionSpec& r : scene.regions) {
      const bool threeD = r.shape->dimension() == 3;
      const bool here = threeD ? r.shape->sectionAt(z) != nullptr : present(r.zRange, z);
      regions.push_back(here);
      cut = cut || (here && threeD);
    }
    if (slabs.empty() || slabs.back().regions != regions || cut) slabs.push_back({{}, std::move(regions)});
    slabs.back().z.push_back(z);
  }
  return slabs;
}

const Region* sectionOf(const RegionSpec& r, double z, std::unique_ptr<Region>& cut) {
  if (r.shape->dimension() != 3) return present(r.zRange, z) ? r.shape.get() : nullptr;
  cut = r.shape->sectionAt(z);
  return cut.get();
}

long layersIn(const Scene& scene, const std::optional<ZRange>& range) {
  long n = 0;
  for (const double z : extrusionLayers(scene)) n += present(range, z) ? 1 : 0;
  return n;
}

}  // namespace isph
