#include "particleGeneration/SpatialHash.hpp"

#include <cmath>

namespace isph {

std::int64_t SpatialHash::cellIndex(double v) const {
  return static_cast<std::int64_t>(std::floor(v / cell_));
}

void SpatialHash::insert(const Vec2& p) {
  cells_[key(cellIndex(p.x()), cellIndex(p.y()))].push_back(
      static_cast<std::uint32_t>(points_.size()));
  points_.push_back(p);
}

double SpatialHash::nearestDistance(const Vec2& p, double r) const {
  double best2 = r * r;
  const std::int64_t ci = cellIndex(p.x()), cj = cellIndex(p.y());
  for (std::int64_t i = ci - 1; i <= ci + 1; ++i) {
    for (std::int64_t j = cj - 1; j <= cj + 1; ++j) {
      const auto it = cells_.find(key(i, j));
      if (it == cells_.end()) continue;
      for (const std::uint32_t k : it->second)
        best2 = std::min(best2, (points_[k] - p).squaredNorm());
    }
  }
  return std::sqrt(best2);
}

}  // namespace isph
