// Transform: rotation about z through an origin, then translation; quarter turns are exact.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/Transform.hpp"

namespace isph {
namespace {

TEST(Transform, IdentityByDefault) {
  const Transform t;
  EXPECT_TRUE(t.isIdentity());
  EXPECT_EQ(t.point(Vec3(1, 2, 0)), Vec3(1, 2, 0));
}

TEST(Transform, QuarterTurnIsExact) {
  const Transform t(90, Vec3(1, 0, 0), Vec3(0, 0, 0));
  EXPECT_EQ(t.point(Vec3(2, 0, 0)), Vec3(1, 1, 0));
  EXPECT_EQ(t.vector(Vec3(1, 0, 0)), Vec3(0, 1, 0));
}

TEST(Transform, SlopeAlignedFlume) {
  // rotate -45: the bed (x axis) descends at 45°; translate moves the origin.
  const Transform t(-45, Vec3::Zero(), Vec3(0, 2, 0));
  const Vec3 x = t.point(Vec3(std::sqrt(2.0), 0, 0));
  EXPECT_NEAR(x.x(), 1.0, 1e-15);
  EXPECT_NEAR(x.y(), 1.0, 1e-15);
  const Vec3 n = t.vector(Vec3(0, 1, 0));
  EXPECT_NEAR(n.x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(n.y(), std::sqrt(0.5), 1e-15);
  const Vec3 back = t.inverseVector(n);
  EXPECT_NEAR(back.x(), 0, 1e-15);
  EXPECT_NEAR(back.y(), 1, 1e-15);
}

}  // namespace
}  // namespace isph
