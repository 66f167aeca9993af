#include "geometry/Segment.hpp"

#include <algorithm>
#include <cmath>

namespace isph {

double closestParameter(const Vec2& a, const Vec2& b, const Vec2& p) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0.0) return 0.0;
  return std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
}

double distanceSquared(const Vec2& a, const Vec2& b, const Vec2& p) {
  const double t = closestParameter(a, b, p);
  return (a + t * (b - a) - p).squaredNorm();
}

namespace {

// Sign of the turn a -> b -> c, with a tolerance relative to the segment lengths.
int orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
  const double v = cross(b - a, c - a);
  const double scale = (b - a).norm() * (c - a).norm();
  if (std::abs(v) <= 1e-12 * scale) return 0;
  return v > 0 ? 1 : -1;
}

// For collinear a, b, p: whether p lies within the box of a-b.
bool onSegment(const Vec2& a, const Vec2& b, const Vec2& p) {
  return p.x() <= std::max(a.x(), b.x()) && p.x() >= std::min(a.x(), b.x()) &&
         p.y() <= std::max(a.y(), b.y()) && p.y() >= std::min(a.y(), b.y());
}

}  // namespace

void rayCrossings(const std::vector<Vec2>& points, const Vec2& o, const Vec2& d,
                  std::vector<double>& t) {
  for (std::size_t i = 0, n = points.size(); i < n; ++i) {
    const Vec2& a = points[i];
    const Vec2 e = points[(i + 1) % n] - a;
    const double denom = cross(d, e);
    if (std::abs(denom) <= 1e-14 * d.norm() * e.norm()) continue;
    const double s = cross(a - o, d) / denom;
    const double ti = cross(a - o, e) / denom;
    if (s >= -1e-12 && s <= 1 + 1e-12 && ti > 0) t.push_back(ti);
  }
}

bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && onSegment(a, b, c)) || (o2 == 0 && onSegment(a, b, d)) ||
         (o3 == 0 && onSegment(c, d, a)) || (o4 == 0 && onSegment(c, d, b));
}

}  // namespace isph
