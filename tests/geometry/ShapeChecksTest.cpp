// The validity checks of user-given point lists, with the point to blame.
#include <gtest/gtest.h>

#include "geometry/ShapeChecks.hpp"

namespace isph {
namespace {

TEST(ShapeChecks, ValidShapesPass) {
  EXPECT_FALSE(polygonProblem({{0, 0}, {1, 0}, {0, 1}}));
  EXPECT_FALSE(polygonProblem({{0, 0}, {1, 0}, {0, 1}, {0, 0}}));  // closed explicitly
  EXPECT_FALSE(polylineProblem({{0, 1}, {0, 0}, {3, 0}}));
  EXPECT_FALSE(profileCurveProblem({{3, 0}, {2, 1}, {0, 1}}));
}

TEST(ShapeChecks, PolygonNeedsThreePoints) {
  const auto p = polygonProblem({{0, 0}, {1, 0}});
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("at least 3"), std::string::npos);
}

TEST(ShapeChecks, SelfIntersectingPolygon) {
  const auto p = polygonProblem({{0, 0}, {1, 1}, {1, 0}, {0, 1}});  // a bow tie
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("crosses itself"), std::string::npos) << p->message;
  EXPECT_GE(p->point, 0);
}

TEST(ShapeChecks, DegeneratePolygons) {
  auto p = polygonProblem({{0, 0}, {1, 1}, {2, 2}});
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("fold"), std::string::npos) << p->message;
  p = polygonProblem({{0, 0}, {1, 0}, {1, 0}, {0, 1}});
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("coincide"), std::string::npos);
  EXPECT_EQ(p->point, 2);
}

TEST(ShapeChecks, PolylineFoldingBackOrCrossing) {
  auto p = polylineProblem({{0, 0}, {2, 0}, {1, 0}});
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("folds back"), std::string::npos);
  p = polylineProblem({{0, 0}, {2, 0}, {2, 1}, {1, -1}});
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("crosses itself"), std::string::npos);
}

TEST(ShapeChecks, ProfileCurvesMustBeMonotoneAndNotCross) {
  auto p = profileCurveProblem({{0, 0}, {2, 0}, {1, 1}});
  ASSERT_TRUE(p);
  EXPECT_EQ(p->point, 2);
  p = profileBandProblem({{0, 1}, {4, -1}}, {{0, 0}, {4, 0}});
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("cross"), std::string::npos);
  p = profileBandProblem({{0, 1}, {1, 1}}, {{2, 0}, {4, 0}});
  ASSERT_TRUE(p);
  EXPECT_NE(p->message.find("share no x range"), std::string::npos);
  EXPECT_FALSE(
      profileBandProblem({{0, 0}, {2, 1}, {4, 0}}, {{0, 0}, {4, 0}}));  // touching at the ends
}

}  // namespace
}  // namespace isph
