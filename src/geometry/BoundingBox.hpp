#pragma once
// An axis-aligned bounding box; empty until a point is added. 2D shapes leave z at 0.
#include <string>

#include "core/Types.hpp"

namespace isph {

struct BoundingBox {
  Vec3 min = Vec3::Constant(1e300);
  Vec3 max = Vec3::Constant(-1e300);

  BoundingBox() = default;
  BoundingBox(const Vec3& lo, const Vec3& hi) : min(lo), max(hi) {}

  bool empty() const { return (min.array() > max.array()).any(); }
  void extend(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  void extend(const BoundingBox& b) {
    if (b.empty()) return;
    extend(b.min);
    extend(b.max);
  }
  bool contains(const Vec3& p) const {
    return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
  }
  bool overlaps(const BoundingBox& b) const {
    return (min.array() <= b.max.array()).all() && (b.min.array() <= max.array()).all();
  }
  // Grown by `d` on every side (x and y only for 2D boxes whose z extent is zero).
  BoundingBox inflated(double d) const;
  Vec3 size() const { return empty() ? Vec3::Zero() : Vec3(max - min); }

  // "(x y z) (x y z)", six significant digits.
  std::string str() const;
};

}  // namespace isph
