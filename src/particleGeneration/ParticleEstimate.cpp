#include "particleGeneration/ParticleEstimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/io/ReadFile.hpp"
#include "particleGeneration/Extrusion.hpp"
#include "particleGeneration/ZSlabs.hpp"

namespace isph {

ParticleEstimate estimateParticles(const Scene& scene) {
  const Lattice lattice(scene.lattice, scene.spacing, scene.latticeOrigin);
  ParticleEstimate e;
  const bool threeD = scene.dimension == 3;  // the section repeated along z (Extrusion.hpp)
  for (const RegionSpec& r : scene.regions) {
    e.material += r.shape->dimension() == 3
                      ? r.shape->measure() / (lattice.siteArea() * scene.spacing)
                      : r.shape->measure() / lattice.siteArea() * (threeD ? static_cast<double>(layersIn(scene, r.zRange)) : 1.0);
    const BoundingBox box = r.shape->boundingBox();
    if (box.empty()) continue;
    // Lattice::range's columns and rows, in floating point (no overflow for any spacing).
    e.tested +=
        (box.size().x() / lattice.spacing() + 3) * (box.size().y() / lattice.rowSpacing() + 3);
  }
  BoundingBox walls;
  for (const WallSpec& w : scene.walls) {
    e.walls += (w.surface->chain().length() / scene.spacing + 1) * scene.wallLayers *
               (threeD ? static_cast<double>(extrusionLayers(scene).size()) : 1.0);
    walls.extend(w.surface->boundingBox().inflated((scene.wallLayers - 1) * scene.spacing));  // the dummies' reach
  }
  if (threeD) {  // the side walls
    if (scene.sideWalls && !walls.empty()) {
      walls.min.head<2>() = walls.min.head<2>().cwiseMax(scene.sideWalls->min);  // their extent
      walls.max.head<2>() = walls.max.head<2>().cwiseMin(scene.sideWalls->max);
      e.walls += 2.0 * scene.wallLayers * (walls.size().x() / scene.spacing + 1) * (walls.size().y() / scene.spacing + 1);
    }
  }
  return e;
}

void checkParticleEstimate(const Scene& scene, const ParticleEstimate& estimate) {
  // The filling tests every site of the regions' bounding boxes: a scene may test many more
  // than it fills, but not without bound (a hundred times the limit takes hours).
  const double tested = estimate.tested / 100;
  const double n = std::max(estimate.particles(), tested);
  if (n <= scene.maxParticles) return;
  const SourceLocation& where =
      scene.maxParticlesWhere.file ? scene.maxParticlesWhere : scene.spacingWhere;
  const std::string count =
      n == estimate.particles()
          ? fmt::format("about {:.3g} particles ({:.3g} material, {:.3g} wall and dummy)",
                        estimate.particles(), estimate.material, estimate.walls)
          : fmt::format(
                "{:.3g} lattice sites to test in the regions' bounding boxes (for {:.3g} "
                "particles)",
                estimate.tested, estimate.particles());
  fatalIOError(
      where,
      fmt::format("spacing {} m gives {}, more than maxParticles {:.3g}.\n"
                  "    Memory: particleMesh about {}, the solver about {} to {} (2.4-4.6 KB per "
                  "particle).\n"
                  "    Check the spacing (in metres); for a scene this large raise maxParticles in "
                  "system/particleMeshDict.",
                  scene.spacing, count, scene.maxParticles, bytesText(estimate.generationBytes()),
                  bytesText(estimate.particles() * ParticleEstimate::solverBytesPerParticle[0]),
                  bytesText(estimate.particles() * ParticleEstimate::solverBytesPerParticle[1])));
}

}  // namespace isph
