#pragma once
// Points bucketed by square cells in a hash map, for "the nearest point within r" queries
// without testing all pairs. Cells have side `cellSize`; a query with r <= cellSize looks at
// the 3 × 3 cells around the point. Insert and query interleave freely (greedy de-duplication).
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "geometry/Vec2.hpp"

namespace isph {

class SpatialHash {
 public:
  explicit SpatialHash(double cellSize) : cell_(cellSize) {}

  void insert(const Vec2& p);
  std::size_t size() const { return points_.size(); }
  const Vec2& point(std::size_t k) const { return points_[k]; }

  // Distance to the nearest stored point closer than r (r <= cellSize), or r when none is.
  double nearestDistance(const Vec2& p, double r) const;
  bool anyCloserThan(const Vec2& p, double r) const { return nearestDistance(p, r) < r; }

 private:
  std::int64_t cellIndex(double v) const;
  static std::uint64_t key(std::int64_t i, std::int64_t j) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) << 32) |
           static_cast<std::uint32_t>(j);
  }

  double cell_;
  std::vector<Vec2> points_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace isph
