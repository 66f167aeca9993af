#include "geometry/Box.hpp"

#include "geometry/Segment.hpp"

namespace isph {

Box::Box(const Vec2& min, const Vec2& max) : min_(min.cwiseMin(max)), max_(min.cwiseMax(max)) {}

bool Box::contains(const Vec3& p) const {
  return p.x() >= min_.x() && p.x() < max_.x() && p.y() >= min_.y() && p.y() < max_.y();
}

BoundingBox Box::boundingBox() const { return {toVec3(min_), toVec3(max_)}; }

void Box::rayCrossings(const Vec3& o, const Vec3& d, std::vector<double>& t) const {
  isph::rayCrossings(corners(), toVec2(o), toVec2(d), t);
}

double Box::measure() const { return (max_ - min_).prod(); }

std::vector<Vec2> Box::corners() const {
  return {min_, {max_.x(), min_.y()}, max_, {min_.x(), max_.y()}};
}

}  // namespace isph
