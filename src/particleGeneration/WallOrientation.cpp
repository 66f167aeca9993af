#include "particleGeneration/WallOrientation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace isph {

namespace {

bool inMaterial(const Vec2& p, const std::vector<const Region*>& material) {
  const Vec3 x = toVec3(p);
  for (const Region* r : material) {
    if (r->contains(x)) return true;
  }
  return false;
}

WallSide vote(const WallSurface& wall, const std::vector<const Region*>& material, double dx,
              double reach) {
  WallSide side;
  side.automatic = true;
  const Polyline& chain = wall.chain();
  for (std::size_t s = 0; s < chain.segmentCount(); ++s) {
    const long parts = std::max(1L, std::lround(chain.segmentLength(s) / dx));
    const Vec2 n = chain.normal(s);
    for (long i = 0; i < parts; ++i) {
      const double t = (static_cast<double>(i) + 0.5) / static_cast<double>(parts);
      const Vec2 p = chain.segmentStart(s) + t * (chain.segmentEnd(s) - chain.segmentStart(s));
      for (double d = 0.5 * dx; d < reach; d += dx) {
        side.probesLeft += inMaterial(p + d * n, material);
        side.probesRight += inMaterial(p - d * n, material);
      }
    }
  }
  return side;
}

}  // namespace

std::vector<WallSurface> orientWalls(const std::vector<WallSpec>& walls,
                                     const std::vector<const Region*>& material, double dx,
                                     double reach, std::vector<WallSide>& sides) {
  std::vector<WallSurface> out;
  sides.assign(walls.size(), WallSide{});
  for (std::size_t w = 0; w < walls.size(); ++w) {
    WallSurface surface = *walls[w].surface;
    WallSide& side = sides[w];
    if (!surface.isClosed()) {
      if (walls[w].side == MaterialSide::automatic) {
        side = vote(surface, material, dx, reach);
        if (side.probesLeft == side.probesRight) {
          fatalIOError(
              walls[w].where,
              fmt::format(
                  "cannot tell which side of wall '{}' the material is on (within {:.4g} m of it, "
                  "{} "
                  "probes find material on its left, {} on its right); set `materialSide left;` or "
                  "`right;` in it (left: on the left walking from its first point to its last)",
                  walls[w].name, reach, side.probesLeft, side.probesRight));
        }
        side.reversed = side.probesRight > side.probesLeft;
      } else {
        side.reversed = walls[w].side == MaterialSide::right;
      }
      if (side.reversed) surface.flip();
    }
    out.push_back(std::move(surface));
  }
  return out;
}

}  // namespace isph
