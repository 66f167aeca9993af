#include "isph/regularisation/ParticleCollision.hpp"

#include <cmath>
#include <vector>

#include "isph/parallel/GhostExchange.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

CollisionResult separateCloseParticles(ParticleSystem& ps, double distance) {
  CollisionResult result;
  if (distance <= 0) return result;
  auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const double dmin = distance * ps.dx;
  const long n = static_cast<long>(ps.nMaterial);
  std::vector<Vec3> dx(ps.nMaterial, Vec3::Zero()), du(ps.nMaterial, Vec3::Zero());
  long moved = 0;
#pragma omp parallel for schedule(static) reduction(+ : moved)
  for (long ia = 0; ia < n; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    bool contact = false;
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto b = static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)]);
      if (!ps.isMaterial(b)) continue;
      const Vec3 xab = c.positions[a] - c.positions[b];
      const double r = xab.norm();
      if (r >= dmin || r == 0) continue;
      const Vec3 e = xab / r;
      const double share = c.mass[b] / (c.mass[a] + c.mass[b]);
      dx[a] += share * (dmin - r) * e;
      const double approach = (c.U[a] - c.U[b]).dot(e);  // < 0: closing
      if (approach < 0) du[a] -= share * approach * e;
      contact = true;
    }
    moved += contact && a < ps.ownMaterial();  // (parallel: the own)
  }
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < n; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    c.positions[a] += dx[a];
    c.U[a] += du[a];
  }
  exchangeGhosts(ps, c.positions);  // parallel
  exchangeGhosts(ps, c.U);
  result.moved = sumOverRanks(static_cast<std::size_t>(moved));
  return result;
}

}  // namespace isph
