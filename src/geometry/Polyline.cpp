#include "geometry/Polyline.hpp"

#include <algorithm>
#include <cmath>

namespace isph {

Polyline::Polyline(std::vector<Vec2> points, bool closed)
    : points_(std::move(points)), closed_(closed) {
  if (closed_ && points_.size() > 1 && points_.front() == points_.back()) points_.pop_back();
  std::vector<Vec2> first, second;
  for (std::size_t s = 0; s < segmentCount(); ++s) {
    first.push_back(segmentStart(s));
    second.push_back(segmentEnd(s));
  }
  for (const Vec2& p : points_) box_.extend(toVec3(p));
  tree_ = SegmentTree(std::move(first), std::move(second));
}

double Polyline::length() const {
  double l = 0;
  for (std::size_t s = 0; s < segmentCount(); ++s) l += segmentLength(s);
  return l;
}

Polyline Polyline::reversed() const {
  std::vector<Vec2> p(points_.rbegin(), points_.rend());
  return Polyline(std::move(p), closed_);
}

Polyline::Distance Polyline::signedDistance(const Vec2& p) const {
  Distance out;
  const SegmentTree::Hit hit = tree_.nearest(p);
  if (hit.segment < 0) return out;
  const auto s = static_cast<std::size_t>(hit.segment);
  const std::size_t nSeg = segmentCount();
  out.closest = hit.point;
  const double d = std::sqrt(hit.distanceSquared);
  const Vec2 r = p - hit.point;

  Vec2 n = normal(s);
  const bool atStart = hit.t <= 0.0;
  const bool atEnd = hit.t >= 1.0;
  if (atStart || atEnd) {
    // The nearest point is a vertex: the segments before and after it.
    const bool openEnd = !closed_ && ((atStart && s == 0) || (atEnd && s + 1 == nSeg));
    if (openEnd) {
      const Vec2 t = tangent(s);
      const double along = atStart ? -r.dot(t) : r.dot(t);
      if (along > 1e-12 * std::max(d, 1e-300)) out.beside = true;
    } else {
      const std::size_t other = atStart ? (s + nSeg - 1) % nSeg : (s + 1) % nSeg;
      n = (n + normal(other)).normalized();
    }
  }
  out.signedDistance = r.dot(n) >= 0 ? d : -d;
  return out;
}

}  // namespace isph
