#pragma once
// A rigid motion applied to a whole scene after its particles are generated, so users can
// describe a flume in slope-aligned coordinates (x along the bed, y normal to it) or tilt a
// scene:
//     x' = R(angle) (x - origin) + origin + translate
// R turns counter-clockwise about the z axis by `angle` degrees (rotate -45 tilts a
// slope-aligned flume so that its bed descends at 45° towards +x). Vectors (normals,
// velocities) are rotated only.
#include "core/Types.hpp"

namespace isph {

class Transform {
 public:
  Transform() = default;  // identity
  Transform(double angleDegrees, const Vec3& origin, const Vec3& translate);

  Vec3 point(const Vec3& x) const { return rotation_ * (x - origin_) + origin_ + translate_; }
  Vec3 vector(const Vec3& v) const { return rotation_ * v; }
  Vec3 inverseVector(const Vec3& v) const {
    return rotation_.transpose() * v;
  }  // case -> scene frame
  bool isIdentity() const { return angle_ == 0.0 && translate_.isZero(0.0); }

  double angleDegrees() const { return angle_; }
  const Vec3& origin() const { return origin_; }
  const Vec3& translate() const { return translate_; }

 private:
  double angle_ = 0;
  Vec3 origin_ = Vec3::Zero();
  Vec3 translate_ = Vec3::Zero();
  Eigen::Matrix3d rotation_ = Eigen::Matrix3d::Identity();
};

}  // namespace isph
