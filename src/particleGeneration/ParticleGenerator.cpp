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
#include "particleGeneration/ZSlabs.hpp"

namespace isph {

namespace {

void checkRegionsHoldSites(const Scene& scene, const std::vector<RegionReport>& reports,
                           const Lattice& lattice) {
  for (std::size_t r = 0; r < reports.size(); ++r) {
    if (reports[r].inside > 0) continue;
    const RegionSpec& region = scene.regions[r];
    fatalIOError(
        region.where,
        fmt::format("region '{}' ({}, {} {:.4g} {}) holds no lattice site at spacing {} (one "
                    "site stands for {:.4g} m²): make it larger or the spacing smaller",
                    region.name, region.shape->type(), region.shape->dimension() == 3 ? "volume" : "area",
                    region.shape->measure(), region.shape->dimension() == 3 ? "m³" : "m²", scene.spacing,
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

// One slab's section (ZSlabs.hpp): the material sites of the regions present there, after
// the walls removed theirs.
struct Section {
  std::vector<RegionSites> sites;       // by scene region (empty where absent)
  std::vector<ClearanceCount> removed;  // by scene region
  std::vector<Vec2> material;           // all kept sites, by region
  std::vector<double> nearest;          // their distance to the nearest wall surface (capped at dx)
  std::vector<double> pressure;         // their initial pressure
};

Section buildSection(const Scene& scene, const ZSlab& slab, const std::vector<WallSurface>& walls,
                     const Lattice& lattice) {
  const double dx = scene.spacing;
  const std::size_t nRegions = scene.regions.size();
  std::vector<const Region*> shapes;
  std::vector<std::size_t> regionOf;  // present region -> scene region
  std::vector<std::unique_ptr<Region>> cuts(nRegions);  // 3D regions' sections at this slab
  for (std::size_t r = 0; r < nRegions; ++r) {
    if (!slab.regions[r]) continue;
    shapes.push_back(sectionOf(scene.regions[r], slab.z.front(), cuts[r]));
    regionOf.push_back(r);
  }
  Section section;
  section.sites.resize(nRegions);
  section.removed.resize(nRegions);
  std::vector<RegionSites> filled = fillRegions(shapes, lattice);
  std::vector<double> nearest;
  for (std::size_t q = 0; q < filled.size(); ++q) {
    RegionSites& sites = section.sites[regionOf[q]];
    sites.sites = std::move(filled[q].sites);
    sites.inside = filled[q].inside;
    sites.lostTo.assign(nRegions, 0);
    for (std::size_t e = 0; e < q; ++e) sites.lostTo[regionOf[e]] = filled[q].lostTo[e];
    section.removed[regionOf[q]] = removeBlockedSites(sites.sites, walls, scene.wallClearance * dx, nearest, dx);
    section.material.insert(section.material.end(), sites.sites.begin(), sites.sites.end());
    section.nearest.insert(section.nearest.end(), nearest.begin(), nearest.end());
  }
  section.pressure.assign(section.material.size(), 0.0);
  if (scene.initialPressure == InitialPressure::lithostatic) {
    std::vector<double> densities;
    for (const std::size_t r : regionOf) densities.push_back(scene.regions[r].density);
    const double g = scene.gravity.norm();
    const Vec2 up = toVec2(scene.transform.inverseVector(-scene.gravity / g));
    section.pressure = lithostaticPressure(section.material, shapes, densities, up, g);
  }
  return section;
}

// The extent of the section (scene frame): the material sites of every slab, the wall and
// dummy particles.
BoundingBox sectionBounds(const std::vector<Section>& sections, const std::vector<WallParticle>& walls) {
  BoundingBox box;
  for (const Section& s : sections) {
    for (const Vec2& x : s.material) box.extend(toVec3(x));
  }
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

// The regions' reports, summed over the slabs (3D: counts of particles, sites times layers).
std::vector<RegionReport> regionReports(const Scene& scene, const std::vector<ZSlab>& slabs,
                                        const std::vector<Section>& sections, const Lattice& lattice) {
  const double depth = extrusionDepth(scene);
  std::vector<RegionReport> reports;
  for (std::size_t r = 0; r < scene.regions.size(); ++r) {
    const RegionSpec& spec = scene.regions[r];
    RegionReport report;
    report.name = spec.name;
    report.type = spec.shape->type();
    report.material = scene.materials.at(static_cast<std::size_t>(spec.material));
    report.density = spec.density;
    std::vector<long> lost(scene.regions.size(), 0);
    for (std::size_t s = 0; s < slabs.size(); ++s) {
      if (!slabs[s].regions[r]) continue;
      const long n = static_cast<long>(slabs[s].z.size());
      const RegionSites& sites = sections[s].sites[r];
      report.inside += sites.inside * n;
      for (std::size_t q = 0; q < r; ++q) lost[q] += sites.lostTo[q] * n;
      report.inSolid += sections[s].removed[r].inSolid * n;
      report.nearWall += sections[s].removed[r].nearWall * n;
      report.particles += static_cast<long>(sites.sites.size()) * n;
    }
    for (std::size_t q = 0; q < r; ++q) {
      if (lost[q] > 0) report.lostTo.emplace_back(scene.regions[q].name, lost[q]);
    }
    report.geometricArea = spec.shape->dimension() == 3
                               ? spec.shape->measure()
                               : spec.shape->measure() * depth * static_cast<double>(layersIn(scene, spec.zRange));
    report.particleArea = static_cast<double>(report.particles) * lattice.siteArea() * depth;
    report.mass = report.particleArea * spec.density;
    reports.push_back(std::move(report));
  }
  return reports;
}

// The walls' reports (3D: the section's particles times the layers).
std::vector<WallReport> wallReports(const Scene& scene, const std::vector<WallSurface>& walls,
                                    const std::vector<WallSide>& sides, const WallLayerResult& layers) {
  const auto n = static_cast<long>(extrusionLayers(scene).size());
  std::vector<WallReport> reports;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    WallReport report;
    report.name = scene.walls[w].name;
    report.patch = scene.patches.at(static_cast<std::size_t>(scene.walls[w].patch)).name;
    report.type = walls[w].type();
    report.side = sideText(walls[w], sides[w]);
    report.frictionAngle = scene.patches[static_cast<std::size_t>(scene.walls[w].patch)].frictionAngle;
    report.stats = layers.stats[w];
    report.stats.wallParticles *= n;
    report.stats.dummyParticles *= n;
    reports.push_back(std::move(report));
  }
  return reports;
}

}  // namespace

GenerationResult generateParticles(const Scene& scene) {
  const double dx = scene.spacing;
  const Lattice lattice(scene.lattice, dx, scene.latticeOrigin);
  const ParticleEstimate estimate = estimateParticles(scene);
  checkParticleEstimate(scene, estimate);  // before anything is allocated

  std::vector<const Region*> shapes;  // in x-y: a 3D region's outline
  std::vector<std::unique_ptr<Region>> outlines;
  for (const RegionSpec& r : scene.regions) {
    if (r.shape->dimension() == 3) outlines.push_back(r.shape->outline());
    shapes.push_back(r.shape->dimension() == 3 ? outlines.back().get() : r.shape.get());
  }
  std::vector<WallSide> sides;
  const std::vector<WallSurface> walls =
      orientWalls(scene.walls, shapes, dx, scene.wallLayers * dx, sides);

  // A 3D scene repeats each slab's section along z (Extrusion.hpp, ZSlabs.hpp): one copy per
  // layer, each particle standing for `depth` of width. A 2D scene is one slab at z = 0.
  const std::vector<ZSlab> slabs = zSlabs(scene);
  const double depth = extrusionDepth(scene);
  std::vector<Section> sections;
  {
    const Building building(fmt::format("the material particles of {} region(s) at spacing {} m (about {:.3g} "
                                        "particles, {:.3g} lattice sites tested)",
                                        scene.regions.size(), dx, estimate.material, estimate.tested));
    for (const ZSlab& slab : slabs) sections.push_back(buildSection(scene, slab, walls, lattice));
  }
  GenerationResult result;
  result.regions = regionReports(scene, slabs, sections, lattice);
  checkRegionsHoldSites(scene, result.regions, lattice);
  const Building building(fmt::format("the particle cloud at spacing {} m (about {:.3g} particles: {:.3g} material, "
                                      "{:.3g} wall and dummy)",
                                      dx, estimate.particles(), estimate.material, estimate.walls));
  const WallLayerResult wallLayers = generateWallLayers(walls, scene.wallLayers, dx);
  for (const Section& s : sections) {
    GenerationResult slabPair;
    closestPair(s.material, s.nearest, wallLayers.particles, dx, slabPair);
    if (result.closestPairKinds.empty() || slabPair.closestPair < result.closestPair) {
      result.closestPair = slabPair.closestPair;
      result.closestPairKinds = slabPair.closestPairKinds;
    }
  }

  // The cloud: material particles by region (then slab, layer), then wall and dummy particles
  // by layer (then wall), then the side walls.
  const std::vector<SideWallParticle> sideWalls =
      sideWallParticles(scene, sectionBounds(sections, wallLayers.particles), wallLayers.particles);
  std::size_t materialCount = 0;
  for (std::size_t k = 0; k < slabs.size(); ++k) materialCount += sections[k].material.size() * slabs[k].z.size();
  if (sideWalls.size() > 5 * materialCount) {
    warning(fmt::format("the side walls hold {} particles, {:.0f} times the material's: they cover the section's "
                        "bounding box, walls included; limit them to where the material can go with "
                        "`min (x y 0); max (x y 0);` in sideWalls",
                        sideWalls.size(), static_cast<double>(sideWalls.size()) / std::max<double>(1.0, static_cast<double>(materialCount))),
            scene.sideWalls->where);
  }
  const std::vector<double> layers = extrusionLayers(scene);
  ParticleCloud& cloud = result.cloud;
  cloud.name = scene.cloudName;
  cloud.properties.materials = scene.materials;
  cloud.properties.patches = scene.patches;
  cloud.properties.dimension = scene.dimension;
  cloud.properties.spacing = dx;
  cloud.properties.lattice = toString(scene.lattice);
  std::size_t total = sideWalls.size() + wallLayers.particles.size() * layers.size();
  for (std::size_t k = 0; k < slabs.size(); ++k) total += sections[k].material.size() * slabs[k].z.size();
  cloud.reserve(total);
  const Transform& T = scene.transform;
  const auto at = [&](const Vec2& s, double z) { return T.point(Vec3(s.x(), s.y(), z)); };
  label id = 0;
  std::vector<std::size_t> firstSite(slabs.size(), 0);  // of the region in each slab's section
  for (std::size_t r = 0; r < scene.regions.size(); ++r) {
    const RegionSpec& spec = scene.regions[r];
    const double mass = spec.density * lattice.siteArea() * depth;
    const Vec3 U = T.vector(spec.initialVelocity);
    for (std::size_t k = 0; k < slabs.size(); ++k) {
      const std::vector<Vec2>& sites = sections[k].sites[r].sites;
      for (const double z : slabs[k].z) {
        for (std::size_t s = 0; s < sites.size(); ++s) {
          const Vec3 x = at(sites[s], z);
          cloud.push_back(x, id++, U, sections[k].pressure[firstSite[k] + s], spec.material, ParticleKind::material,
                          -1, Vec3::Zero(), mass);
          result.regions[r].bounds.extend(x);
        }
      }
      firstSite[k] += sites.size();
    }
  }
  result.walls = wallReports(scene, walls, sides, wallLayers);
  for (const double z : layers) {
    for (const WallParticle& p : wallLayers.particles) {
      const WallSpec& spec = scene.walls[static_cast<std::size_t>(p.wall)];
      const Vec3 x = at(p.position, z);
      cloud.push_back(x, id++, Vec3::Zero(), 0.0, -1, p.isWall ? ParticleKind::wall : ParticleKind::dummy,
                      spec.patch, T.vector(toVec3(p.normal)), spec.density * dx * dx * depth);
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
