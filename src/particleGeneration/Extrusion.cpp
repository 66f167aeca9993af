#include "particleGeneration/Extrusion.hpp"

#include <algorithm>
#include <cmath>

#include "particleGeneration/Lattice.hpp"
#include "particles/MaterialSideOfWalls.hpp"

namespace isph {

namespace {

long layerCount(const Scene& scene) {
  return std::max(1L, std::lround(scene.width / scene.spacing));
}

// The section's wall particles (kind wall, x-y at z = 0) as MaterialSideOfWalls reads them.
MaterialSideOfWalls sectionSides(const std::vector<WallParticle>& section, double dx) {
  std::vector<MaterialSideOfWalls::WallPoint> walls;
  for (const WallParticle& w : section) {
    if (w.isWall) walls.push_back({toVec3(w.position), toVec3(w.normal), w.wall});
  }
  return MaterialSideOfWalls(std::move(walls), dx);
}

}  // namespace

std::vector<double> extrusionLayers(const Scene& scene) {
  if (scene.dimension != 3) return {0.0};
  std::vector<double> z;
  for (long k = 0; k < layerCount(scene); ++k) z.push_back((static_cast<double>(k) + 0.5) * scene.spacing);
  return z;
}

double extrusionDepth(const Scene& scene) { return scene.dimension == 3 ? scene.spacing : 1.0; }

std::vector<SideWallParticle> sideWallParticles(const Scene& scene, const BoundingBox& section,
                                                const std::vector<WallParticle>& walls) {
  std::vector<SideWallParticle> out;
  if (scene.dimension != 3 || !scene.sideWalls || section.empty()) return out;
  const double dx = scene.spacing;
  const Lattice lattice(LatticeType::square, dx, scene.latticeOrigin);
  BoundingBox covered = section;  // clipped to the side walls' own extent (SideWallSpec)
  covered.min.head<2>() = covered.min.head<2>().cwiseMax(scene.sideWalls->min);
  covered.max.head<2>() = covered.max.head<2>().cwiseMin(scene.sideWalls->max);
  if (covered.empty()) return out;
  const SiteRange range = lattice.range(covered);
  const MaterialSideOfWalls sides = sectionSides(walls, dx);
  const double deepest = (scene.wallLayers - 0.5) * dx;  // a dummy's reach, as in 2D
  std::vector<std::pair<Vec2, bool>> sites;  // x-y, and whether the section's walls make it solid
  for (long j = range.j0; j <= range.j1; ++j) {
    for (long i = range.i0; i <= range.i1; ++i) {
      const Vec2 s = lattice.site(i, j);
      if (!covered.contains(toVec3(s))) continue;
      const auto verdict = sides.empty() ? MaterialSideOfWalls::Verdict{} : sides.classify(toVec3(s));
      const bool solid = verdict.side != MaterialSideOfWalls::Side::material;
      if (solid && -verdict.depth > deepest) continue;
      sites.emplace_back(s, solid);
    }
  }
  const double far = static_cast<double>(layerCount(scene)) * dx;
  for (int end = 0; end < 2; ++end) {
    const double outward = end == 0 ? -1.0 : 1.0;
    for (int m = 0; m < scene.wallLayers; ++m) {
      const double z = (end == 0 ? 0.0 : far) + outward * m * dx;
      for (const auto& [s, solid] : sites) {
        SideWallParticle p;
        p.end = end;
        p.position = Vec3(s.x(), s.y(), z);
        p.isWall = m == 0 && !solid;
        if (p.isWall) p.normal = Vec3(0, 0, -outward);
        out.push_back(p);
      }
    }
  }
  return out;
}

}  // namespace isph
