#pragma once
// A simple polygon (closed implicitly: the last vertex connects to the first), stored
// counter-clockwise whatever the winding it was given in. Check user input with
// polygonProblem (ShapeChecks.hpp) first: the constructor assumes a valid polygon.
#include <vector>

#include "geometry/Region.hpp"
#include "geometry/SegmentTree.hpp"
#include "geometry/Vec2.hpp"

namespace isph {

// Twice the signed area (positive counter-clockwise) of the closed chain `points`.
double signedDoubleArea(const std::vector<Vec2>& points);

class Polygon : public Region {
 public:
  // A repeated first vertex at the end is dropped.
  explicit Polygon(std::vector<Vec2> vertices);

  std::string type() const override { return "polygon"; }
  bool contains(const Vec3& p) const override { return contains(toVec2(p)); }
  BoundingBox boundingBox() const override { return box_; }
  void rayCrossings(const Vec3& o, const Vec3& d, std::vector<double>& t) const override;
  double measure() const override { return area_; }

  // Crossing-number test, half-open as Region::contains.
  bool contains(const Vec2& p) const;
  // Distance to the boundary, negative inside.
  double signedDistance(const Vec2& p) const;
  const std::vector<Vec2>& vertices() const { return vertices_; }  // counter-clockwise
  double area() const { return area_; }

 private:
  std::vector<Vec2> vertices_;
  double area_ = 0;
  BoundingBox box_;
  SegmentTree edges_;
};

}  // namespace isph
