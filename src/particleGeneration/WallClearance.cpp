#include "particleGeneration/WallClearance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace isph {

namespace {

enum Blocked : std::uint8_t { open = 0, inSolid = 1, nearWall = 2 };

Blocked blocked(const Vec2& p, const std::vector<WallSurface>& walls,
                const std::vector<BoundingBox>& reach, double clearance, double& nearest) {
  Blocked result = open;
  for (std::size_t w = 0; w < walls.size(); ++w) {
    // A closed solid cannot block a site away from its box; a polyline's solid is unbounded.
    if (walls[w].isClosed() && !reach[w].contains(toVec3(p))) continue;
    const auto d = walls[w].distance(p);
    if (d.signedDistance < 0 && !d.beside) return inSolid;
    nearest = std::min(nearest, std::abs(d.signedDistance));
    if (std::abs(d.signedDistance) < clearance) result = nearWall;
  }
  return result;
}

}  // namespace

ClearanceCount removeBlockedSites(std::vector<Vec2>& sites, const std::vector<WallSurface>& walls,
                                  double clearance, std::vector<double>& nearestSurface,
                                  double cap) {
  ClearanceCount count;
  nearestSurface.assign(sites.size(), cap);
  if (walls.empty()) return count;
  std::vector<BoundingBox> reach;
  for (const WallSurface& w : walls)
    reach.push_back(w.boundingBox().inflated(std::max(clearance, cap)));
  const double limit = clearance * (1 - 1e-9);  // sites at exactly the clearance are kept

  std::vector<Blocked> flag(sites.size());
  const long n = static_cast<long>(sites.size());
#pragma omp parallel for schedule(static)
  for (long k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    flag[i] = blocked(sites[i], walls, reach, limit, nearestSurface[i]);
  }

  std::size_t kept = 0;
  for (std::size_t k = 0; k < sites.size(); ++k) {
    if (flag[k] == inSolid) ++count.inSolid;
    if (flag[k] == nearWall) ++count.nearWall;
    if (flag[k] == open) {
      nearestSurface[kept] = nearestSurface[k];
      sites[kept++] = sites[k];
    }
  }
  sites.resize(kept);
  nearestSurface.resize(kept);
  return count;
}

}  // namespace isph
