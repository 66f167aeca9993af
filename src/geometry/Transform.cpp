#include "geometry/Transform.hpp"

#include <cmath>
#include <numbers>

namespace isph {

Transform::Transform(double angleDegrees, const Vec3& origin, const Vec3& translate)
    : angle_(angleDegrees), origin_(origin), translate_(translate) {
  const double a = angleDegrees * std::numbers::pi / 180.0;
  // Exact values for multiples of 90° keep axis-aligned scenes exactly axis-aligned.
  double c = std::cos(a), s = std::sin(a);
  if (std::fmod(angleDegrees, 90.0) == 0.0) {
    c = std::round(c);
    s = std::round(s);
  }
  rotation_ << c, -s, 0, s, c, 0, 0, 0, 1;
}

}  // namespace isph
