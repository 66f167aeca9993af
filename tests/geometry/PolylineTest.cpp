// Polyline: signed distance positive on the left, the pseudo-normal at both kinds of corner,
// `beside` past an open end, closed chains.
#include <gtest/gtest.h>

#include "geometry/Polyline.hpp"

namespace isph {
namespace {

TEST(Polyline, LeftIsPositive) {
  const Polyline bed({{0, 0}, {10, 0}});
  EXPECT_DOUBLE_EQ(bed.signedDistance(Vec2(3, 2)).signedDistance, 2.0);
  EXPECT_DOUBLE_EQ(bed.signedDistance(Vec2(3, -1)).signedDistance, -1.0);
  EXPECT_FALSE(bed.signedDistance(Vec2(3, -1)).beside);
  EXPECT_EQ(bed.normal(0), Vec2(0, 1));
  EXPECT_DOUBLE_EQ(bed.reversed().signedDistance(Vec2(3, 2)).signedDistance, -2.0);
}

TEST(Polyline, PastAnOpenEndIsBeside) {
  const Polyline bed({{0, 0}, {10, 0}});
  EXPECT_TRUE(bed.signedDistance(Vec2(11, -1)).beside);
  EXPECT_TRUE(bed.signedDistance(Vec2(-1, 1)).beside);
  EXPECT_FALSE(bed.signedDistance(Vec2(10, -1)).beside);  // straight behind the end point
  EXPECT_DOUBLE_EQ(bed.signedDistance(Vec2(11, 0)).signedDistance, 1.0);
}

TEST(Polyline, CornersUseThePseudoNormal) {
  // A tank's floor and right wall: material inside (left), a concave corner at (10, 0).
  const Polyline tank({{0, 5}, {0, 0}, {10, 0}, {10, 5}});
  EXPECT_GT(tank.signedDistance(Vec2(9, 1)).signedDistance, 0);
  EXPECT_LT(tank.signedDistance(Vec2(11, -1)).signedDistance, 0);  // nearest point is the corner
  EXPECT_NEAR(tank.signedDistance(Vec2(11, -1)).signedDistance, -std::sqrt(2.0), 1e-12);
  // A step down (convex corner at (5, 2)): points beyond the corner diagonally are in front.
  const Polyline step({{0, 2}, {5, 2}, {5, 0}, {10, 0}});
  EXPECT_GT(step.signedDistance(Vec2(6, 3)).signedDistance, 0);
  EXPECT_LT(step.signedDistance(Vec2(4, 1)).signedDistance, 0);
}

TEST(Polyline, ClosedChainWalkedClockwiseHasTheOutsideOnTheLeft) {
  const Polyline solid({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, true);  // clockwise
  EXPECT_EQ(solid.segmentCount(), 4u);
  EXPECT_GT(solid.signedDistance(Vec2(2, 0.5)).signedDistance, 0);
  EXPECT_GT(solid.signedDistance(Vec2(2, 2)).signedDistance, 0);
  EXPECT_NEAR(solid.signedDistance(Vec2(0.5, 0.4)).signedDistance, -0.4, 1e-12);
  EXPECT_DOUBLE_EQ(solid.length(), 4.0);
}

}  // namespace
}  // namespace isph
