#pragma once
// The band between two profiles of the scene frame, for example the ground surface above and
// a slip surface below. Material lies ABOVE `lower` and BELOW the top, where the top is
// `upper`, or `lower + thickness` (measured along y), or the lower of the two when both are
// given (a layer of given thickness that stops at the ground surface). Both curves are
// polylines whose x increases strictly (decreasing lists are reversed); the band spans the x
// range the curves share. Check the input first with profileProblem (ShapeChecks.hpp).
#include <optional>
#include <vector>

#include "geometry/Region.hpp"
#include "geometry/Vec2.hpp"

namespace isph {

// y of the polyline `curve` (x increasing) at x, linear between points, clamped at the ends.
double interpolateProfile(const std::vector<Vec2>& curve, double x);

class Profile : public Region {
 public:
  // `upper` may be empty when a thickness is given.
  Profile(std::vector<Vec2> upper, std::vector<Vec2> lower, std::optional<double> thickness = {});

  std::string type() const override { return "profile"; }
  bool contains(const Vec3& p) const override;
  BoundingBox boundingBox() const override { return box_; }
  void rayCrossings(const Vec3& o, const Vec3& d, std::vector<double>& t) const override;
  double measure() const override { return area_; }

  double top(double x) const;
  double bottom(double x) const { return interpolateProfile(lower_, x); }
  double xBegin() const { return x0_; }
  double xEnd() const { return x1_; }
  // The sorted x of both curves' points (and of the crossings of upper and lower + thickness)
  // within [xBegin, xEnd]: between two of them top - bottom is linear.
  const std::vector<double>& breakpoints() const { return breaks_; }

 private:
  std::vector<Vec2> upper_, lower_;
  std::optional<double> thickness_;
  double x0_ = 0, x1_ = 0, area_ = 0;
  std::vector<double> breaks_;
  std::vector<Vec2> outline_;  // the boundary: bottom at the breakpoints, then the top back
  BoundingBox box_;
};

}  // namespace isph
