#pragma once
// An axis-aligned rectangle [min, max) of the scene frame.
#include <vector>

#include "geometry/Region.hpp"
#include "geometry/Vec2.hpp"

namespace isph {

class Box : public Region {
 public:
  Box(const Vec2& min, const Vec2& max);

  std::string type() const override { return "box"; }
  bool contains(const Vec3& p) const override;
  BoundingBox boundingBox() const override;
  void rayCrossings(const Vec3& o, const Vec3& d, std::vector<double>& t) const override;
  double measure() const override;

  const Vec2& min() const { return min_; }
  const Vec2& max() const { return max_; }
  // The four corners, counter-clockwise from min.
  std::vector<Vec2> corners() const;

 private:
  Vec2 min_, max_;
};

}  // namespace isph
