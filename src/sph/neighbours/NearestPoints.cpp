#include "sph/neighbours/NearestPoints.hpp"

#include "sph/neighbours/CellGrid.hpp"

namespace isph {

std::vector<int> nearestPoints(const std::vector<Vec3>& targets, const std::vector<label>& targetIds,
                               const std::vector<Vec3>& queries, double radius, int dimension) {
  std::vector<int> nearest(queries.size(), -1);
  if (targets.empty()) return nearest;
  const CellGrid grid(targets, radius, dimension);
  const auto& n = grid.counts();
  const double radius2 = radius * radius;
  const long nq = static_cast<long>(queries.size());
#pragma omp parallel for schedule(static)
  for (long iq = 0; iq < nq; ++iq) {
    const Vec3& x = queries[static_cast<std::size_t>(iq)];
    const auto c = grid.cellOf(x);
    double best = radius2;
    int found = -1;
    for (int k = dimension == 3 ? c[2] - 1 : 0; k <= (dimension == 3 ? c[2] + 1 : 0); ++k) {
      if (k < 0 || k >= n[2]) continue;
      for (int j = c[1] - 1; j <= c[1] + 1; ++j) {
        if (j < 0 || j >= n[1]) continue;
        for (int i = c[0] - 1; i <= c[0] + 1; ++i) {
          if (i < 0 || i >= n[0]) continue;
          const long cell = grid.index({i, j, k});
          for (int s = grid.cellStart()[static_cast<std::size_t>(cell)];
               s < grid.cellStart()[static_cast<std::size_t>(cell) + 1]; ++s) {
            const int t = grid.sorted()[static_cast<std::size_t>(s)];
            const double r2 = (x - targets[static_cast<std::size_t>(t)]).squaredNorm();
            if (r2 < best || (r2 == best && found >= 0 &&
                              targetIds[static_cast<std::size_t>(t)] < targetIds[static_cast<std::size_t>(found)])) {
              best = r2;
              found = t;
            }
          }
        }
      }
    }
    nearest[static_cast<std::size_t>(iq)] = found;
  }
  return nearest;
}

}  // namespace isph
