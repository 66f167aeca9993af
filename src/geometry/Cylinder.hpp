#pragma once
// A vertical circular cylinder of the scene frame (a 3D region): its axis along y through
// (x0, z0), radius R, from y0 to y0 + H. Inside: (x - x0)² + (z - z0)² < R² and y0 <= y <
// y0 + H. Its section at z is the box |x - x0| < w, y0 <= y < y0 + H with
// w = sqrt(R² - (z - z0)²) (none where |z - z0| >= R): particleMesh fills each layer with it.
#include "geometry/Region.hpp"

namespace isph {

class Cylinder : public Region {
 public:
  Cylinder(const Vec3& baseCentre, double radius, double height);

  std::string type() const override { return "cylinder"; }
  int dimension() const override { return 3; }
  bool contains(const Vec3& p) const override;
  BoundingBox boundingBox() const override;
  double measure() const override;  // π R² H
  void rayCrossings(const Vec3& o, const Vec3& d, std::vector<double>& t) const override;
  std::unique_ptr<Region> sectionAt(double z) const override;
  std::unique_ptr<Region> outline() const override;  // the section through the axis

 private:
  Vec3 base_;
  double radius_, height_;
};

}  // namespace isph
