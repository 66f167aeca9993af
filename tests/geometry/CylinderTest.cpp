// Cylinder (geometry/Cylinder.hpp): a vertical cylinder, base centre (0.2, 0.1, 0.3), radius
// 0.05, height 0.04. Inside and outside by the circle and the height (half-open at the top);
// its volume; a ray's crossings (mantle and caps) at their exact parameters; its section at z
// is the box of half-width sqrt(R² - (z - z0)²), none outside the circle, and its outline the
// section through the axis.
#include "geometry/Cylinder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace isph {
namespace {

const Cylinder cylinder(Vec3(0.2, 0.1, 0.3), 0.05, 0.04);

TEST(Cylinder, InsideByTheCircleAndTheHeight) {
  EXPECT_EQ(cylinder.dimension(), 3);
  EXPECT_TRUE(cylinder.contains(Vec3(0.2, 0.1, 0.3)));  // the base centre (bottom: inside)
  EXPECT_TRUE(cylinder.contains(Vec3(0.2 + 0.049, 0.12, 0.3)));
  EXPECT_TRUE(cylinder.contains(Vec3(0.2 + 0.03, 0.12, 0.3 + 0.039)));  // 0.0492 from the axis
  EXPECT_FALSE(cylinder.contains(Vec3(0.2 + 0.03, 0.12, 0.3 + 0.041)));  // 0.0507
  EXPECT_FALSE(cylinder.contains(Vec3(0.2, 0.14, 0.3)));  // the top: outside
  EXPECT_FALSE(cylinder.contains(Vec3(0.2, 0.099, 0.3)));
  EXPECT_NEAR(cylinder.measure(), M_PI * 0.05 * 0.05 * 0.04, 1e-15);
  const BoundingBox b = cylinder.boundingBox();
  EXPECT_NEAR((b.min - Vec3(0.15, 0.1, 0.25)).norm(), 0, 1e-15);
  EXPECT_NEAR((b.max - Vec3(0.25, 0.14, 0.35)).norm(), 0, 1e-15);
}

TEST(Cylinder, RayCrossesTheMantleAndTheCaps) {
  std::vector<double> t;
  cylinder.rayCrossings(Vec3(0, 0.12, 0.3), Vec3(1, 0, 0), t);  // along x through the axis
  std::sort(t.begin(), t.end());
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 0.15, 1e-12);
  EXPECT_NEAR(t[1], 0.25, 1e-12);
  t.clear();
  cylinder.rayCrossings(Vec3(0.21, 0, 0.3), Vec3(0, 1, 0), t);  // up through both caps
  std::sort(t.begin(), t.end());
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 0.1, 1e-12);
  EXPECT_NEAR(t[1], 0.14, 1e-12);
  t.clear();
  cylinder.rayCrossings(Vec3(0.3, 0, 0.3), Vec3(0, 1, 0), t);  // up beside it
  EXPECT_TRUE(t.empty());
}

TEST(Cylinder, ItsSectionAtZIsABoxOfTheChordsHalfWidth) {
  const auto mid = cylinder.sectionAt(0.3);
  ASSERT_TRUE(mid);
  EXPECT_NEAR(mid->measure(), 0.1 * 0.04, 1e-15);
  const auto off = cylinder.sectionAt(0.33);  // half-width sqrt(0.05² - 0.03²) = 0.04
  ASSERT_TRUE(off);
  EXPECT_NEAR((off->boundingBox().min - Vec3(0.16, 0.1, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((off->boundingBox().max - Vec3(0.24, 0.14, 0)).norm(), 0, 1e-12);
  EXPECT_FALSE(cylinder.sectionAt(0.351));
  EXPECT_FALSE(cylinder.sectionAt(0.2));
  EXPECT_NEAR(cylinder.outline()->measure(), 0.1 * 0.04, 1e-15);
}

}  // namespace
}  // namespace isph
