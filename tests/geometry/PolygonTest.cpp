// Polygon and Box: area in either winding, the half-open inside test, signed distance and the
// ray crossings that lithostatic pressure integrates along.
#include <gtest/gtest.h>

#include <algorithm>

#include "geometry/Box.hpp"
#include "geometry/Polygon.hpp"

namespace isph {
namespace {

const std::vector<Vec2> square{{0, 0}, {2, 0}, {2, 1}, {0, 1}};

TEST(Polygon, AreaDoesNotDependOnWinding) {
  std::vector<Vec2> clockwise(square.rbegin(), square.rend());
  EXPECT_DOUBLE_EQ(Polygon(square).area(), 2.0);
  EXPECT_DOUBLE_EQ(Polygon(clockwise).area(), 2.0);
  EXPECT_GT(signedDoubleArea(Polygon(clockwise).vertices()), 0.0);  // stored counter-clockwise
}

TEST(Polygon, RepeatedFirstPointIsDropped) {
  std::vector<Vec2> closed = square;
  closed.push_back(square.front());
  EXPECT_EQ(Polygon(closed).vertices().size(), 4u);
  EXPECT_DOUBLE_EQ(Polygon(closed).area(), 2.0);
}

TEST(Polygon, InsideIsHalfOpenLikeBox) {
  const Polygon p(square);
  const Box b({0, 0}, {2, 1});
  for (const Vec2& q : {Vec2(1, 0.5), Vec2(0, 0.5), Vec2(2, 0.5), Vec2(1, 0), Vec2(1, 1),
                        Vec2(-0.1, 0.5), Vec2(1, 1.1)}) {
    EXPECT_EQ(p.contains(q), b.contains(toVec3(q))) << q.transpose();
  }
  EXPECT_TRUE(p.contains(Vec2(0, 0.5)));   // left edge inside
  EXPECT_FALSE(p.contains(Vec2(2, 0.5)));  // right edge outside
  EXPECT_TRUE(p.contains(Vec2(1, 0)));     // bottom inside
  EXPECT_FALSE(p.contains(Vec2(1, 1)));    // top outside
}

TEST(Polygon, ConcavePolygon) {
  // An L: the notch (1..2, 1..2) is outside.
  const Polygon l({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  EXPECT_DOUBLE_EQ(l.area(), 3.0);
  EXPECT_TRUE(l.contains(Vec2(0.5, 1.5)));
  EXPECT_FALSE(l.contains(Vec2(1.5, 1.5)));
  EXPECT_NEAR(l.signedDistance(Vec2(1.5, 1.5)), 0.5, 1e-12);
  EXPECT_NEAR(l.signedDistance(Vec2(0.5, 0.5)), -0.5, 1e-12);
}

TEST(Polygon, RayCrossingsGiveTheChord) {
  const Polygon p(square);
  std::vector<double> t;
  p.rayCrossings(Vec3(1, -1, 0), Vec3(0, 1, 0), t);
  std::sort(t.begin(), t.end());
  ASSERT_EQ(t.size(), 2u);
  EXPECT_DOUBLE_EQ(t[0], 1.0);
  EXPECT_DOUBLE_EQ(t[1], 2.0);
  t.clear();
  p.rayCrossings(Vec3(1, 0.5, 0), Vec3(0, 1, 0), t);  // from inside: one crossing
  ASSERT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t[0], 0.5);
  t.clear();
  Box({0, 0}, {2, 1}).rayCrossings(Vec3(1, 0.5, 0), Vec3(0, -1, 0), t);
  ASSERT_EQ(t.size(), 1u);
  EXPECT_DOUBLE_EQ(t[0], 0.5);
}

TEST(Box, MeasureAndBoundingBox) {
  const Box b({1, 2}, {4, 3});
  EXPECT_DOUBLE_EQ(b.measure(), 3.0);
  EXPECT_EQ(b.boundingBox().min, Vec3(1, 2, 0));
  EXPECT_EQ(b.boundingBox().max, Vec3(4, 3, 0));
  EXPECT_DOUBLE_EQ(Polygon(b.corners()).area(), 3.0);
}

}  // namespace
}  // namespace isph
