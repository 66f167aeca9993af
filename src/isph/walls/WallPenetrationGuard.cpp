#include "isph/walls/WallPenetrationGuard.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "isph/parallel/GhostExchange.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

WallGuardResult guardWallPenetration(ParticleSystem& ps, double distance) {
  WallGuardResult result;
  if (!anyRank(ps.nWall > 0)) return result;
  auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const double dmin = distance * ps.dx;
  const long n = static_cast<long>(ps.nMaterial);
  long moved = 0, crossed = 0;
  // The lowest index that crossed, as the max of −a − 1 (none: the lowest long, which every
  // candidate beats; a start of −1 was particle 0's and named it for every crossing).
  long first = std::numeric_limits<long>::min();
#pragma omp parallel for schedule(static) reduction(+ : moved, crossed) reduction(max : first)
  for (long a = 0; a < n; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    const auto begin = static_cast<std::size_t>(nl.start[ua]);
    const auto end = static_cast<std::size_t>(nl.start[ua + 1]);
    double best = 1e300;
    std::size_t wall = 0;
    for (std::size_t k = begin; k < end; ++k) {
      const auto b = static_cast<std::size_t>(nl.index[k]);
      if (!ps.isWall(b)) continue;
      const double r2 = (c.positions[ua] - c.positions[b]).squaredNorm();
      if (r2 < best) {
        best = r2;
        wall = b;
      }
    }
    if (best == 1e300) continue;
    // The nearest wall particle's concave partner (the header): none where there is none.
    const Vec3& nw = c.normal[wall];
    const double reach = std::sqrt(best) + 0.5 * ps.dx;
    double partnerR2 = reach * reach;
    std::size_t partner = wall;
    for (std::size_t k = begin; k < end; ++k) {
      const auto b = static_cast<std::size_t>(nl.index[k]);
      if (!ps.isWall(b) || b == wall) continue;
      const Vec3 wb = c.positions[b] - c.positions[wall];
      if (wb.dot(nw) <= 0.1 * ps.dx || wb.dot(c.normal[b]) > 1e-9 * ps.dx) continue;
      const double r2 = (c.positions[ua] - c.positions[b]).squaredNorm();
      if (r2 < partnerR2) {
        partnerR2 = r2;
        partner = b;
      }
    }
    const bool own = ua < ps.ownMaterial();  // (parallel: count the own)
    bool behind = false, close = false;
    const auto hold = [&](std::size_t w) {  // in front of w's plane by dmin
      const Vec3& normal = c.normal[w];
      const double dn = (c.positions[ua] - c.positions[w]).dot(normal);
      behind = behind || dn < 0;
      if (dn < dmin * (1.0 - 1e-9)) {
        c.positions[ua] += (dmin - dn) * normal;
        const double un = c.U[ua].dot(normal);
        if (un < 0) c.U[ua] -= un * normal;
        close = true;
      }
    };
    hold(wall);
    if (partner != wall) hold(partner);
    if (behind && own) {
      ++crossed;
      first = std::max(first, -a - 1);  // the lowest index (max of negatives)
    }
    moved += close && own;
  }
  exchangeGhosts(ps, c.positions);  // parallel: the step's last move
  exchangeGhosts(ps, c.U);
  result.moved = sumOverRanks(static_cast<std::size_t>(moved));
  result.crossed = sumOverRanks(static_cast<std::size_t>(crossed));
  if (crossed == 0 && result.crossed > 0) result.firstCrossing = "on another rank";
  if (crossed > 0) {
    const auto a = static_cast<std::size_t>(-first - 1);
    result.firstCrossing = fmt::format("particle {} (origId {}) was behind a wall and was put back at ({:.4g} {:.4g} {:.4g})",
                                       a, c.origId[a], c.positions[a].x(), c.positions[a].y(), c.positions[a].z());
  }
  return result;
}

}  // namespace isph
