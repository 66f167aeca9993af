#pragma once
// A chain of straight segments through a list of points: open (a bed, a slope, a floor) or
// closed (the boundary of a solid). "Left" is the side on the left when walking from the
// first point to the last; signed distances are positive there. Check user input with
// polylineProblem / polygonProblem (ShapeChecks.hpp) first.
#include <vector>

#include "geometry/BoundingBox.hpp"
#include "geometry/SegmentTree.hpp"
#include "geometry/Vec2.hpp"

namespace isph {

class Polyline {
 public:
  Polyline() = default;
  explicit Polyline(std::vector<Vec2> points, bool closed = false);

  const std::vector<Vec2>& points() const { return points_; }
  bool closed() const { return closed_; }
  std::size_t segmentCount() const { return closed_ ? points_.size() : points_.size() - 1; }
  const Vec2& segmentStart(std::size_t s) const { return points_[s]; }
  const Vec2& segmentEnd(std::size_t s) const { return points_[(s + 1) % points_.size()]; }
  double segmentLength(std::size_t s) const { return (segmentEnd(s) - segmentStart(s)).norm(); }
  Vec2 tangent(std::size_t s) const { return (segmentEnd(s) - segmentStart(s)).normalized(); }
  Vec2 normal(std::size_t s) const { return leftNormal(tangent(s)); }  // unit, to the left
  double length() const;
  BoundingBox boundingBox() const { return box_; }

  // The same chain walked the other way (left and right swap).
  Polyline reversed() const;

  struct Distance {
    double signedDistance = 0;  // positive on the left
    bool beside = false;        // open chain: p lies beyond an end point (neither left nor right)
    Vec2 closest = Vec2::Zero();
  };
  // The side is that of the nearest point: the segment's normal there, or at a vertex the
  // mean of its two segments' normals (the pseudo-normal, right for both kinds of corner).
  Distance signedDistance(const Vec2& p) const;

 private:
  std::vector<Vec2> points_;
  bool closed_ = false;
  BoundingBox box_;
  SegmentTree tree_;
};

}  // namespace isph
