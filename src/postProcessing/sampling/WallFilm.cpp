#include "postProcessing/sampling/WallFilm.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/Error.hpp"
#include "sph/neighbours/CellGrid.hpp"
#include "sph/neighbours/NearestPoints.hpp"

namespace isph {

namespace {

// The wall's inclination to the horizontal exceeds its friction angle: the angle between its
// normal and up is larger than δ (a hair of tolerance so that a level floor is level).
bool steeperThanFriction(const Vec3& normal, const Vec3& up, double frictionAngleDeg) {
  const double c = std::clamp(normal.normalized().dot(up), -1.0, 1.0);
  const double inclination = std::acos(c) * 180.0 / std::numbers::pi;
  return inclination > frictionAngleDeg + 1e-6;
}

// How far from the wall w the material reaches along the line x_i + s n: the farthest centre
// within half a spacing of the line, plus half a spacing (searched in `grid`'s 3^D cells
// around x_i, which cover (maxThickness + 1) dx).
double thicknessOver(const ParticleCloud& cloud, const std::vector<Vec3>& material, const CellGrid& grid, int i, int w,
                     double dx) {
  const Vec3& xi = cloud.positions[static_cast<std::size_t>(i)];
  const Vec3& xw = cloud.positions[static_cast<std::size_t>(w)];
  const Vec3 n = cloud.normal[static_cast<std::size_t>(w)].normalized();
  double reach = (xi - xw).dot(n) + 0.5 * dx;
  grid.forEachCandidate(xi, [&](int j) {
    const Vec3& xj = material[static_cast<std::size_t>(j)];
    const Vec3 d = xj - xi;
    if ((d - d.dot(n) * n).norm() < 0.5 * dx) reach = std::max(reach, (xj - xw).dot(n) + 0.5 * dx);
  });
  return reach;
}

}  // namespace

WallFilm restingWallFilm(const ParticleCloud& cloud, const WallFilmSpec& spec) {
  const double dx = cloud.properties.spacing;
  const double gNorm = spec.g.norm();
  if (!(gNorm > 0)) fatalError("wall film: gravity is zero, so no wall is steeper than another");
  if (!(dx > 0)) fatalError(fmt::format("wall film: the cloud's spacing is {}, expected a positive length", dx));
  if (!(spec.restSpeed > 0)) fatalError(fmt::format("wall film: restSpeed {}: expected a positive speed", spec.restSpeed));
  if (!(spec.maxThickness > 0)) {
    fatalError(fmt::format("wall film: maxThickness {}: expected a positive number of spacings", spec.maxThickness));
  }
  const Vec3 up = -spec.g / gNorm;
  const int dim = cloud.properties.dimension;
  const double maxReach = spec.maxThickness * dx;

  std::vector<int> wallIds, resting;
  std::vector<Vec3> materialPoints, wallPoints, restingPoints;
  std::vector<label> wallOrigIds;
  for (std::size_t a = 0; a < cloud.size(); ++a) {
    const auto kind = static_cast<ParticleKind>(cloud.kind[a]);
    if (kind == ParticleKind::material) {
      materialPoints.push_back(cloud.positions[a]);
      if (cloud.U[a].norm() < spec.restSpeed) {
        resting.push_back(static_cast<int>(a));
        restingPoints.push_back(cloud.positions[a]);
      }
    } else if (kind == ParticleKind::wall) {
      wallIds.push_back(static_cast<int>(a));
      wallPoints.push_back(cloud.positions[a]);
      wallOrigIds.push_back(cloud.origId[a]);
    }
  }

  WallFilm film;
  film.resting = static_cast<long>(resting.size());
  if (resting.empty() || wallIds.empty()) return film;
  const std::vector<int> nearest = nearestPoints(wallPoints, wallOrigIds, restingPoints, maxReach, dim);
  const CellGrid grid(materialPoints, maxReach + dx, dim);
  for (std::size_t r = 0; r < resting.size(); ++r) {
    if (nearest[r] < 0) continue;
    const int i = resting[r];
    const int w = wallIds[static_cast<std::size_t>(nearest[r])];
    const label patch = cloud.patch[static_cast<std::size_t>(w)];
    const double delta = patch >= 0 && static_cast<std::size_t>(patch) < cloud.properties.patches.size()
                             ? cloud.properties.patches[static_cast<std::size_t>(patch)].frictionAngle
                             : 0.0;
    if (!steeperThanFriction(cloud.normal[static_cast<std::size_t>(w)], up, delta)) continue;
    if (thicknessOver(cloud, materialPoints, grid, i, w, dx) > maxReach) continue;
    const double elevation = cloud.positions[static_cast<std::size_t>(i)].dot(up);
    if (film.particles == 0) film.lowest = film.highest = elevation;
    film.lowest = std::min(film.lowest, elevation);
    film.highest = std::max(film.highest, elevation);
    film.mass += cloud.mass[static_cast<std::size_t>(i)];
    film.members.push_back(i);
    ++film.particles;
  }
  return film;
}

}  // namespace isph
