#include "particleGeneration/ParticleGenerator.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/app/OutOfMemory.hpp"
#include "particleGeneration/Extrusion.hpp"
#include "particleGeneration/LithostaticPressure.hpp"
#include "particleGeneration/ParticleEstimate.hpp"
#include "particleGeneration/RegionFilling.hpp"
#include "particleGeneration/SpatialHash.hpp"
#include "particleGeneration/WallClearance.hpp"
#include "particleGeneration/WallOrientation.hpp"

namespace isph {

namespace {

void checkRegionsHoldSites(const Scene& scene, const std::vector<RegionSites>& sites,
                           const Lattice& lattice) {
  for (std::size_t r = 0; r < sites.size(); ++r) {
    if (sites[r].inside > 0) continue;
    const RegionSpec& region = scene.regions[r];
    fatalIOError(
        region.where,
        fmt::format("region '{}' ({}, area {:.4g} m²) holds no lattice site at spacing {} (one "
                    "site stands for {:.4g} m²): make it larger or the spacing smaller",
                    region.name, region.shape->type(), region.shape->measure(), scene.spacing,
                    lattice.siteArea()));
  }
}

std::string sideText(const WallSurface& surface, const WallSide& side) {
  if (surface.isClosed()) return "outside (solid)";
  const std::string where = side.reversed ? "right" : "left";
  if (!side.automatic) return where;
  return fmt::format("{} (auto: material at {} probes left, {} right)", where, side.probesLeft,
                     side.probesRight);
}

// Smallest distance between particles of the cloud (scene frame). Lattice sites are dx apart,
// so only pairs with a wall or dummy particle need a search, and only for material within dx
// of a wall surface (wall particles lie on surfaces, dummies behind them).
void closestPair(const std::vector<Vec2>& material, const std::vector<double>& nearestSurface,
                 const std::vector<WallParticle>& walls, double dx, GenerationResult& result) {
  result.closestPair = dx;
  result.closestPairKinds = "material-material";
  SpatialHash hash(dx);
  for (const WallParticle& w : walls) {
    const double d = hash.nearestDistance(w.position, dx);
    if (d < result.closestPair) {
      result.closestPair = d;
      result.closestPairKinds = "wall-wall";
    }
    hash.insert(w.position);
  }
  double nearest = dx;
  const long n = static_cast<long>(material.size());
#pragma omp parallel for reduction(min : nearest)
  for (long k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (nearestSurface[i] < dx) nearest = std::min(nearest, hash.nearestDistance(material[i], dx));
  }
  if (nearest < result.closestPair) {
    result.closestPair = nearest;
    result.closestPairKinds = "material-wall";
  }
}

// The section's extent (scene frame): its material sites, wall and dummy particles.
BoundingBox sectionBounds(const std::vector<Vec2>& material, const std::vector<WallParticle>& walls) {
  BoundingBox box;
  for (const Vec2& s : material) box.extend(toVec3(s));
  for (const WallParticle& w : walls) box.extend(toVec3(w.position));
  return box;
}

// The report of the side wall at z = 0 (end 0) or z = width (end 1).
WallReport sideWallReport(const Scene& scene, const std::vector<SideWallParticle>& particles, int end) {
  const auto patch = static_cast<std::size_t>(scene.sideWalls->patch[end]);
  const double width = static_cast<double>(extrusionLayers(scene).size()) * scene.spacing;
  WallReport report;
  report.name = end == 0 ? "sideWall0" : "sideWall1";
  report.patch = scene.patches.at(patch).name;
  report.type = "side";
  report.side = end == 0 ? std::string("z > 0 (3D)") : fmt::format("z < {:.6g} (3D)", width);
  report.frictionAngle = scene.patches[patch].frictionAngle;
  for (const SideWallParticle& p : particles) {
    if (p.end == end) ++(p.isWall ? report.stats.wallParticles : report.stats.dummyParticles);
  }
  report.stats.minSpacing = report.stats.maxSpacing = scene.spacing;
  return report;
}

}  // namespace

GenerationResult generateParticles(const Scene& scene) {
  const double dx = scene.spacing;
  const Lattice lattice(scene.lattice, dx, scene.latticeOrigin);
  const ParticleEstimate estimate = estimateParticles(scene);
  checkParticleEstimate(scene, estimate);  // before anything is allocated

  std::vector<const Region*> shapes;
  for (const RegionSpec& r : scene.regions) shapes.push_back(r.shape.get());
  std::vector<RegionSites> sites;
  {
    const Building building(fmt::format("the material particles of {} region(s) at spacing {} m (about {:.3g} "
                                        "particles, {:.3g} lattice sites tested)",
                                        scene.regions.size(), dx, estimate.material, estimate.tested));
    sites = fillRegions(shapes, lattice);
  }
  checkRegionsHoldSites(scene, sites, lattice);

  std::vector<WallSide> sides;
  const std::vector<WallSurface> walls =
      orientWalls(scene.walls, shapes, dx, scene.wallLayers * dx, sides);
  const Building building(fmt::format("the particle cloud at spacing {} m (about {:.3g} particles: {:.3g} material, "
                                      "{:.3g} wall and dummy)",
                                      dx, estimate.particles(), estimate.material, estimate.walls));
  const WallLayerResult wallLayers = generateWallLayers(walls, scene.wallLayers, dx);

  // A 3D scene repeats the section along z (Extrusion.hpp): one copy per layer, each particle
  // standing for `depth` of width.
  const std::vector<double> layers = extrusionLayers(scene);
  const double depth = extrusionDepth(scene);
  const double nLayers = static_cast<double>(layers.size());

  GenerationResult result;
  std::vector<Vec2> materialPositions;
  std::vector<double> nearestSurface, allNearest;
  for (std::size_t r = 0; r < sites.size(); ++r) {
    const RegionSpec& spec = scene.regions[r];
    RegionReport report;
    report.name = spec.name;
    report.type = spec.shape->type();
    report.material = scene.materials.at(static_cast<std::size_t>(spec.material));
    report.density = spec.density;
    report.inside = sites[r].inside;
    for (std::size_t q = 0; q < r; ++q) {
      if (sites[r].lostTo[q] > 0)
        report.lostTo.emplace_back(scene.regions[q].name, sites[r].lostTo[q]);
    }
    const ClearanceCount removed =
        removeBlockedSites(sites[r].sites, walls, scene.wallClearance * dx, nearestSurface, dx);
    report.inSolid = removed.inSolid;
    report.nearWall = removed.nearWall;
    report.particles = static_cast<long>(sites[r].sites.size() * layers.size());
    report.geometricArea = spec.shape->measure() * depth * nLayers;
    report.particleArea = static_cast<double>(report.particles) * lattice.siteArea() * depth;
    report.mass = report.particleArea * spec.density;
    result.regions.push_back(std::move(report));
    materialPositions.insert(materialPositions.end(), sites[r].sites.begin(), sites[r].sites.end());
    allNearest.insert(allNearest.end(), nearestSurface.begin(), nearestSurface.end());
  }
  closestPair(materialPositions, allNearest, wallLayers.particles, dx, result);

  const Transform& T = scene.transform;
  std::vector<double> pressure(materialPositions.size(), 0.0);  // of the section's sites
  if (scene.initialPressure == InitialPressure::lithostatic) {
    std::vector<double> densities;
    for (const RegionSpec& r : scene.regions) densities.push_back(r.density);
    const double g = scene.gravity.norm();
    const Vec2 up = toVec2(T.inverseVector(-scene.gravity / g));
    pressure = lithostaticPressure(materialPositions, shapes, densities, up, g);
  }

  // The cloud: material particles by region (then layer), then wall and dummy particles by
  // wall (then layer), then the side walls.
  const std::vector<SideWallParticle> sideWalls =
      sideWallParticles(scene, sectionBounds(materialPositions, wallLayers.particles), wallLayers.particles);
  ParticleCloud& cloud = result.cloud;
  cloud.name = scene.cloudName;
  cloud.properties.materials = scene.materials;
  cloud.properties.patches = scene.patches;
  cloud.properties.dimension = scene.dimension;
  cloud.properties.spacing = dx;
  cloud.properties.lattice = toString(scene.lattice);
  cloud.reserve((materialPositions.size() + wallLayers.particles.size()) * layers.size() + sideWalls.size());
  const auto at = [&](const Vec2& s, double z) { return T.point(Vec3(s.x(), s.y(), z)); };
  label id = 0;
  std::size_t site = 0;
  for (std::size_t r = 0; r < sites.size(); ++r) {
    const RegionSpec& spec = scene.regions[r];
    const double mass = spec.density * lattice.siteArea() * depth;
    const Vec3 U = T.vector(spec.initialVelocity);
    for (const double z : layers) {
      for (std::size_t s = 0; s < sites[r].sites.size(); ++s) {
        const Vec3 x = at(sites[r].sites[s], z);
        cloud.push_back(x, id++, U, pressure[site + s], spec.material, ParticleKind::material, -1, Vec3::Zero(),
                        mass);
        result.regions[r].bounds.extend(x);
      }
    }
    site += sites[r].sites.size();
  }
  for (std::size_t w = 0; w < walls.size(); ++w) {
    WallReport report;
    report.name = scene.walls[w].name;
    report.patch = scene.patches.at(static_cast<std::size_t>(scene.walls[w].patch)).name;
    report.type = walls[w].type();
    report.side = sideText(walls[w], sides[w]);
    report.frictionAngle =
        scene.patches[static_cast<std::size_t>(scene.walls[w].patch)].frictionAngle;
    report.stats = wallLayers.stats[w];
    report.stats.wallParticles *= static_cast<long>(layers.size());
    report.stats.dummyParticles *= static_cast<long>(layers.size());
    result.walls.push_back(std::move(report));
  }
  for (const double z : layers) {
    for (const WallParticle& p : wallLayers.particles) {
      const WallSpec& spec = scene.walls[static_cast<std::size_t>(p.wall)];
      const Vec3 x = at(p.position, z);
      cloud.push_back(x, id++, Vec3::Zero(), 0.0, -1,
                      p.isWall ? ParticleKind::wall : ParticleKind::dummy, spec.patch,
                      T.vector(toVec3(p.normal)), spec.density * dx * dx * depth);
      result.walls[static_cast<std::size_t>(p.wall)].bounds.extend(x);
    }
  }
  const std::size_t firstSide = result.walls.size();
  if (!sideWalls.empty()) {
    for (int end = 0; end < 2; ++end) result.walls.push_back(sideWallReport(scene, sideWalls, end));
    if (layers.front() < result.closestPair) {  // the first layer of material, dx/2 from z = 0
      result.closestPair = layers.front();
      result.closestPairKinds = "material-wall";
    }
  }
  for (const SideWallParticle& p : sideWalls) {
    const Vec3 x = T.point(p.position);
    cloud.push_back(x, id++, Vec3::Zero(), 0.0, -1, p.isWall ? ParticleKind::wall : ParticleKind::dummy,
                    scene.sideWalls->patch[p.end], T.vector(p.normal), scene.sideWalls->density * dx * dx * dx);
    result.walls[firstSide + static_cast<std::size_t>(p.end)].bounds.extend(x);
  }
  return result;
}

}  // namespace isph
