#include "geometry/BoundingBox.hpp"

#include <fmt/format.h>

namespace isph {

BoundingBox BoundingBox::inflated(double d) const {
  if (empty()) return *this;
  BoundingBox b = *this;
  const bool flat = max.z() == min.z();
  b.min -= Vec3(d, d, flat ? 0.0 : d);
  b.max += Vec3(d, d, flat ? 0.0 : d);
  return b;
}

std::string BoundingBox::str() const {
  if (empty()) return "(empty)";
  return fmt::format("({:.6g} {:.6g} {:.6g}) ({:.6g} {:.6g} {:.6g})", min.x(), min.y(), min.z(),
                     max.x(), max.y(), max.z());
}

}  // namespace isph
