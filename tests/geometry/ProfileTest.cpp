// Profile: the band between two x-monotone curves, capped by a thickness; exact area,
// half-open inside test, boundary for ray crossings.
#include <gtest/gtest.h>

#include <algorithm>

#include "geometry/Profile.hpp"

namespace isph {
namespace {

TEST(Profile, AreaOfALens) {
  // Ground surface a roof shape over a flat slip surface; they meet at both ends.
  const Profile p({{0, 0}, {2, 1}, {4, 0}}, {{0, 0}, {4, 0}});
  EXPECT_DOUBLE_EQ(p.measure(), 2.0);
  EXPECT_TRUE(p.contains(Vec3(2, 0.5, 0)));
  EXPECT_FALSE(p.contains(Vec3(2, 1.5, 0)));
  EXPECT_FALSE(p.contains(Vec3(2, -0.1, 0)));
  EXPECT_TRUE(p.contains(Vec3(2, 0.0, 0)));   // on the lower curve: inside
  EXPECT_FALSE(p.contains(Vec3(4, 0.0, 0)));  // x range is half-open
}

TEST(Profile, DecreasingXIsReversedAndRangeIsShared) {
  const Profile p({{5, 2}, {-1, 2}}, {{0, 0}, {4, 0}});
  EXPECT_DOUBLE_EQ(p.xBegin(), 0.0);
  EXPECT_DOUBLE_EQ(p.xEnd(), 4.0);
  EXPECT_DOUBLE_EQ(p.measure(), 8.0);
}

TEST(Profile, ThicknessAloneAndCappedByTheGround) {
  const std::vector<Vec2> slip{{0, 0}, {10, 5}};
  const Profile layer({}, slip, 0.5);
  EXPECT_NEAR(layer.measure(), 5.0, 1e-12);
  EXPECT_NEAR(layer.top(4), 2.5, 1e-12);
  // The ground meets the slip surface at x = 0 and rises faster: the cap acts near x = 0 only.
  const Profile capped({{0, 0}, {10, 10}}, slip, 0.5);
  EXPECT_NEAR(capped.top(0.5), 0.5, 1e-12);  // ground
  EXPECT_NEAR(capped.top(4), 2.5, 1e-12);    // slip + thickness
  // Exact: the cap crosses at x = 1 (x = x/2 + 0.5); triangle 0..1 plus band 1..10.
  EXPECT_NEAR(capped.measure(), 0.5 * 1 * 0.5 + 9 * 0.5, 1e-12);
}

TEST(Profile, RayCrossingsThroughTheBand) {
  const Profile p({{0, 2}, {4, 2}}, {{0, 0}, {4, 0}});
  std::vector<double> t;
  p.rayCrossings(Vec3(1, 0.5, 0), Vec3(0, 1, 0), t);
  std::sort(t.begin(), t.end());
  ASSERT_FALSE(t.empty());
  EXPECT_DOUBLE_EQ(t.back(), 1.5);
}

}  // namespace
}  // namespace isph
