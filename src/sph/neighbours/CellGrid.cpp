#include "sph/neighbours/CellGrid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"

namespace isph {

CellGrid::CellGrid(const std::vector<Vec3>& points, double cellSize, int dimension)
    : dimension_(dimension), cellSize_(cellSize) {
  if (!(cellSize > 0)) fatalError("CellGrid: the cell size must be positive");
  Vec3 lo = Vec3::Constant(0), hi = Vec3::Constant(0);
  if (!points.empty()) {
    lo = hi = points[0];
    for (const auto& x : points) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
  }
  origin_ = lo;
  for (int d = 0; d < 3; ++d) {
    const bool active = d < dimension;
    const double extent = hi[d] - lo[d];
    if (!std::isfinite(extent)) fatalError("CellGrid: a particle position is not finite (NaN or infinite)");
    const double cells = active ? std::floor(extent / cellSize) + 1 : 1;
    if (cells > 1e7) {
      fatalError(fmt::format("CellGrid: the particles span {:.4g} m in direction {}, {:.3g} cells of {:.4g} m: "
                             "a particle has probably left the domain",
                             extent, "xyz"[d], cells, cellSize));
    }
    n_[static_cast<std::size_t>(d)] = static_cast<int>(cells);
  }
  if (static_cast<double>(n_[0]) * n_[1] * n_[2] > 5e8) {
    fatalError("CellGrid: too many cells (the particle cloud is spread far too wide for its spacing)");
  }

  // Counting sort of the points by cell index (stable, so ties keep their input order).
  const long nc = nCells();
  cellStart_.assign(static_cast<std::size_t>(nc) + 1, 0);
  std::vector<long> cellOfPoint(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    cellOfPoint[i] = index(cellOf(points[i]));
    ++cellStart_[static_cast<std::size_t>(cellOfPoint[i]) + 1];
  }
  for (long c = 0; c < nc; ++c) cellStart_[static_cast<std::size_t>(c) + 1] += cellStart_[static_cast<std::size_t>(c)];
  sorted_.resize(points.size());
  std::vector<int> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    sorted_[static_cast<std::size_t>(fill[static_cast<std::size_t>(cellOfPoint[i])]++)] = static_cast<int>(i);
  }
}

std::array<int, 3> CellGrid::cellOf(const Vec3& x) const {
  std::array<int, 3> c{0, 0, 0};
  for (int d = 0; d < dimension_; ++d) {
    const int k = static_cast<int>(std::floor((x[d] - origin_[d]) / cellSize_));
    c[static_cast<std::size_t>(d)] = std::clamp(k, 0, n_[static_cast<std::size_t>(d)] - 1);
  }
  return c;
}

}  // namespace isph
