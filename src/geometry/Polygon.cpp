#include "geometry/Polygon.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/Segment.hpp"

namespace isph {

double signedDoubleArea(const std::vector<Vec2>& points) {
  double a = 0;
  for (std::size_t i = 0, n = points.size(); i < n; ++i) a += cross(points[i], points[(i + 1) % n]);
  return a;
}

Polygon::Polygon(std::vector<Vec2> vertices) : vertices_(std::move(vertices)) {
  if (vertices_.size() > 1 && vertices_.front() == vertices_.back()) vertices_.pop_back();
  const double a2 = signedDoubleArea(vertices_);
  if (a2 < 0) std::reverse(vertices_.begin(), vertices_.end());
  area_ = 0.5 * std::abs(a2);
  std::vector<Vec2> first, second;
  for (std::size_t i = 0, n = vertices_.size(); i < n; ++i) {
    box_.extend(toVec3(vertices_[i]));
    first.push_back(vertices_[i]);
    second.push_back(vertices_[(i + 1) % n]);
  }
  edges_ = SegmentTree(std::move(first), std::move(second));
}

bool Polygon::contains(const Vec2& p) const {
  if (p.x() < box_.min.x() || p.x() > box_.max.x() || p.y() < box_.min.y() || p.y() > box_.max.y())
    return false;
  bool inside = false;
  for (std::size_t i = 0, n = vertices_.size(), j = n - 1; i < n; j = i++) {
    const Vec2& a = vertices_[i];
    const Vec2& b = vertices_[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

void Polygon::rayCrossings(const Vec3& o, const Vec3& d, std::vector<double>& t) const {
  isph::rayCrossings(vertices_, toVec2(o), toVec2(d), t);
}

double Polygon::signedDistance(const Vec2& p) const {
  const double d = std::sqrt(edges_.nearest(p).distanceSquared);
  return contains(p) ? -d : d;
}

}  // namespace isph
