#include "particleGeneration/GenerationReport.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "core/Log.hpp"
#include "core/Strings.hpp"
#include "particleGeneration/Extrusion.hpp"

namespace isph {

namespace {

std::string vec(const Vec3& v) {
  return fmt::format("({:.6g} {:.6g} {:.6g})", v.x(), v.y(), v.z());
}

template <class T, class F>
std::size_t widest(const std::vector<T>& rows, F name, std::size_t atLeast) {
  std::size_t w = atLeast;
  for (const T& r : rows) w = std::max(w, name(r).size());
  return w;
}

// "1.000" or "-" when the reference is zero.
std::string ratio(double value, double reference) {
  return reference > 0 ? fmt::format("{:.4f}", value / reference) : std::string("-");
}

void logRegions(const Scene& scene, const GenerationResult& result) {
  if (result.regions.empty()) return;
  const bool threeD = scene.dimension == 3;
  const std::size_t w = widest(
      result.regions, [](const RegionReport& r) { return r.name; }, 6);
  const std::size_t wm = widest(
      result.regions, [](const RegionReport& r) { return r.material; }, 8);
  info("\nMaterial regions (the first listed wins where they overlap; {})",
       threeD ? "volumes and masses" : "areas and masses per unit width");
  info(
      "    {:<{}}  {:<8} {:<{}} {:>9} {:>8} {:>8} {:>8} {:>10} {:>12} {:>12} {:>7} {:>12} {:>12} "
      "{:>7}",
      "region", w, "type", "material", wm, "sites", "lost", "inSolid", "nearWall", "particles",
      threeD ? "volume [m3]" : "area [m2]", "geometric", "ratio", threeD ? "mass [kg]" : "mass [kg/m]",
      threeD ? "rho*volume" : "rho*area", "ratio");
  for (const RegionReport& r : result.regions) {
    long lost = 0;
    for (const auto& [name, n] : r.lostTo) lost += n;
    const double expected = r.geometricArea * r.density;
    info(
        "    {:<{}}  {:<8} {:<{}} {:>9} {:>8} {:>8} {:>8} {:>10} {:>12.6g} {:>12.6g} {:>7} "
        "{:>12.6g} {:>12.6g} {:>7}",
        r.name, w, r.type, r.material, wm, r.inside, lost, r.inSolid, r.nearWall, r.particles,
        r.particleArea, r.geometricArea, ratio(r.particleArea, r.geometricArea), r.mass, expected,
        ratio(r.mass, expected));
  }
  for (const RegionReport& r : result.regions) {
    info("    {}: bounding box {}", r.name, r.bounds.str());
    if (!r.lostTo.empty()) {
      std::vector<std::string> parts;
      for (const auto& [name, n] : r.lostTo) parts.push_back(fmt::format("{} to '{}'", n, name));
      info("    {}: sites lost to earlier regions: {}", r.name, join(parts, ", "));
    }
    if (r.particles == 0) warning(fmt::format("region '{}' keeps no particle", r.name));
  }

  // Per material.
  std::map<std::string, std::pair<long, double>> perMaterial;
  for (const RegionReport& r : result.regions) {
    perMaterial[r.material].first += r.particles;
    perMaterial[r.material].second += r.mass;
  }
  info("\nMaterials");
  for (const auto& [name, totals] : perMaterial) {
    info("    {:<{}} {:>10} particles  mass {:.6g} {}", name, wm, totals.first, totals.second,
         threeD ? "kg" : "kg/m");
  }
}

void logWalls(const Scene& scene, const GenerationResult& result) {
  if (result.walls.empty()) return;
  const std::size_t w = widest(
      result.walls, [](const WallReport& r) { return r.name; }, 4);
  const std::size_t wp = widest(
      result.walls, [](const WallReport& r) { return r.patch; }, 5);
  info("\nWalls ({} layers: 1 wall + {} dummy, {:.6g} m apart)", scene.wallLayers,
       scene.wallLayers - 1, scene.spacing);
  info("    {:<{}}  {:<8} {:<{}} {:>6} {:>8} {:>8} {:>8} {:>8} {:>11} {:>15}", "wall", w, "type",
       "patch", wp, "phi", "wall", "dummy", "demoted", "dropped", "length [m]", "spacing [dx]");
  for (const WallReport& r : result.walls) {
    const WallLayerStats& s = r.stats;
    const std::string spacing =
        fmt::format("{:.3f}-{:.3f}", s.minSpacing / scene.spacing, s.maxSpacing / scene.spacing);
    info("    {:<{}}  {:<8} {:<{}} {:>6.4g} {:>8} {:>8} {:>8} {:>8} {:>11.6g} {:>15}", r.name, w,
         r.type, r.patch, wp, r.frictionAngle, s.wallParticles, s.dummyParticles, s.demoted,
         s.dropped, s.surfaceLength, spacing);
  }
  for (const WallReport& r : result.walls) {
    info("    {}: material side {}; bounding box {}", r.name, r.side, r.bounds.str());
  }
}

}  // namespace

void logScene(const Scene& scene) {
  const Lattice lattice(scene.lattice, scene.spacing, scene.latticeOrigin);
  info("\nScene");
  info("    spacing {:.6g} m, {} lattice (site area {:.6g} m2), dimension {}, cloud '{}'",
       scene.spacing, toString(scene.lattice), lattice.siteArea(), scene.dimension,
       scene.cloudName);
  if (scene.dimension == 3) {
    const std::size_t layers = extrusionLayers(scene).size();
    info("    3D: the x-y scene extruded along z over width {:.6g} m: {} layers of dx ({:.6g} m); "
         "side walls: {}",
         scene.width, layers, static_cast<double>(layers) * scene.spacing,
         scene.sideWalls ? fmt::format("patch '{}' at z = 0, '{}' at z = {:.6g}",
                                       scene.patches.at(static_cast<std::size_t>(scene.sideWalls->patch[0])).name,
                                       scene.patches.at(static_cast<std::size_t>(scene.sideWalls->patch[1])).name,
                                       static_cast<double>(layers) * scene.spacing)
                         : std::string("none (the ends are open)"));
  }
  if (scene.transform.isIdentity()) {
    info("    transform: none (scene frame = case frame)");
  } else {
    info("    transform: rotate {:.6g} deg about {}, then translate {}",
         scene.transform.angleDegrees(), vec(scene.transform.origin()),
         vec(scene.transform.translate()));
  }
  info("    wall clearance {:.4g} dx ({:.6g} m)", scene.wallClearance,
       scene.wallClearance * scene.spacing);
  if (scene.initialPressure == InitialPressure::lithostatic) {
    info("    initial pressure: lithostatic along g = {}", vec(scene.gravity));
  } else {
    info("    initial pressure: zero");
  }
}

void logGeneration(const Scene& scene, const GenerationResult& result) {
  logRegions(scene, result);
  logWalls(scene, result);

  const ParticleCloud& cloud = result.cloud;
  long counts[3] = {0, 0, 0};
  BoundingBox bounds;
  double pMax = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    ++counts[cloud.kind[i]];
    bounds.extend(cloud.positions[i]);
    pMax = std::max(pMax, cloud.p[i]);
  }
  info("\nCloud '{}': {} particles ({} material, {} wall, {} dummy)", cloud.name, cloud.size(),
       counts[0], counts[1], counts[2]);
  info("    bounding box {}", bounds.str());
  info("    closest pair {:.4g} dx ({})", result.closestPair / scene.spacing,
       result.closestPairKinds);
  if (scene.initialPressure == InitialPressure::lithostatic)
    info("    initial pressure up to {:.6g} Pa", pMax);
}

}  // namespace isph
