#include "sph/neighbours/NeighbourList.hpp"

#include "sph/neighbours/CellGrid.hpp"
#include "core/ResizeForOverwrite.hpp"

#include <algorithm>
#include <cmath>

namespace isph {

void NeighbourList::build(const std::vector<Vec3>& positions, const Kernel& kernel, std::size_t nMaterial,
                          const std::vector<char>* withRow) {
  const double support = kernel.supportRadius();
  const double support2 = support * support;
  const CellGrid grid(positions, support, kernel.dimension());
  const long n = static_cast<long>(positions.size());
  const long materialEnd = static_cast<long>(std::min(nMaterial, positions.size()));
  // Whether b is in a's row: a material particle's row holds every neighbour, another's the
  // material ones (filtered among the candidates, so that they keep the whole row's order).
  const auto kept = [materialEnd](long a, long b) { return b != a && (a < materialEnd || b < materialEnd); };
  const auto hasRow = [withRow](long a) { return !withRow || (*withRow)[static_cast<std::size_t>(a)] != 0; };

  // Pass 1: count; pass 2: fill. Each particle writes only its own row.
  std::vector<long> count(static_cast<std::size_t>(n) + 1, 0);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const Vec3& xa = positions[static_cast<std::size_t>(a)];
    long c = 0;
    if (hasRow(a)) grid.forEachCandidate(xa, [&](int b) {
      if (kept(a, b) && (xa - positions[static_cast<std::size_t>(b)]).squaredNorm() < support2) ++c;
    });
    count[static_cast<std::size_t>(a) + 1] = c;
  }
  start.assign(static_cast<std::size_t>(n) + 1, 0);
  for (long a = 0; a < n; ++a) start[static_cast<std::size_t>(a) + 1] = start[static_cast<std::size_t>(a)] + count[static_cast<std::size_t>(a) + 1];
  const std::size_t nPairs = static_cast<std::size_t>(start.back());
  resizeForOverwrite(index, nPairs);  // every pair is written below
  resizeForOverwrite(W, nPairs);
  resizeForOverwrite(F, nPairs);

#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const Vec3& xa = positions[static_cast<std::size_t>(a)];
    std::size_t k = static_cast<std::size_t>(start[static_cast<std::size_t>(a)]);
    if (hasRow(a)) grid.forEachCandidate(xa, [&](int b) {
      if (!kept(a, b)) return;
      const double r2 = (xa - positions[static_cast<std::size_t>(b)]).squaredNorm();
      if (r2 >= support2) return;
      const double r = std::sqrt(r2);
      index[k] = b;
      W[k] = kernel.W(r);
      F[k] = r > 0 ? kernel.dWdr(r) / r : 0.0;
      ++k;
    });
  }
}

std::vector<int> cellOrder(const std::vector<Vec3>& positions, double cellSize, int dimension) {
  const CellGrid grid(positions, cellSize, dimension);
  return grid.sorted();
}

}  // namespace isph
