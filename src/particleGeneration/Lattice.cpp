#include "particleGeneration/Lattice.hpp"

#include <cmath>

namespace isph {

const char* toString(LatticeType type) {
  return type == LatticeType::square ? "square" : "hexagonal";
}

Lattice::Lattice(LatticeType type, double dx, const Vec2& origin)
    : type_(type),
      dx_(dx),
      dy_(type == LatticeType::hexagonal ? 0.5 * std::sqrt(3.0) * dx : dx),
      origin_(origin) {}

SiteRange Lattice::range(const BoundingBox& box) const {
  if (box.empty()) return {};
  // One extra column/row on each side covers the half-cell shift and rounding.
  SiteRange r;
  r.i0 = static_cast<long>(std::floor((box.min.x() - origin_.x()) / dx_)) - 1;
  r.i1 = static_cast<long>(std::ceil((box.max.x() - origin_.x()) / dx_));
  r.j0 = static_cast<long>(std::floor((box.min.y() - origin_.y()) / dy_)) - 1;
  r.j1 = static_cast<long>(std::ceil((box.max.y() - origin_.y()) / dy_));
  return r;
}

}  // namespace isph
