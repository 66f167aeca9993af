#include "sph/neighbours/NearestPoints.hpp"

#include "sph/neighbours/CellGrid.hpp"

namespace isph {

std::vector<int> nearestPoints(const std::vector<Vec3>& targets, const std::vector<label>& targetIds,
                               const std::vector<Vec3>& queries, double radius, int dimension) {
  std::vector<int> nearest(queries.size(), -1);
  if (targets.empty()) return nearest;
  const CellGrid grid(targets, radius, dimension);
  const double radius2 = radius * radius;
  const long nq = static_cast<long>(queries.size());
#pragma omp parallel for schedule(static)
  for (long iq = 0; iq < nq; ++iq) {
    const Vec3& x = queries[static_cast<std::size_t>(iq)];
    double best = radius2;
    int found = -1;
    grid.forEachCandidate(x, [&](int t) {
      const double r2 = (x - targets[static_cast<std::size_t>(t)]).squaredNorm();
      if (r2 < best || (r2 == best && found >= 0 &&
                        targetIds[static_cast<std::size_t>(t)] < targetIds[static_cast<std::size_t>(found)])) {
        best = r2;
        found = t;
      }
    });
    nearest[static_cast<std::size_t>(iq)] = found;
  }
  return nearest;
}

}  // namespace isph
