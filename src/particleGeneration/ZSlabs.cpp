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
    for (const RegionSpec& r : scene.regions) regions.push_back(present(r.zRange, z));
    if (slabs.empty() || slabs.back().regions != regions) slabs.push_back({{}, std::move(regions)});
    slabs.back().z.push_back(z);
  }
  return slabs;
}

long layersIn(const Scene& scene, const std::optional<ZRange>& range) {
  long n = 0;
  for (const double z : extrusionLayers(scene)) n += present(range, z) ? 1 : 0;
  return n;
}

}  // namespace isph
