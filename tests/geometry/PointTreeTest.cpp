// PointTree (geometry/PointTree.hpp) against a loop over all points: the nearest point and the
// points within a radius, for random points in 2D (z = 0, as the walls of a plane scene) and 3D,
// for ties (the lowest index), a query far outside, and an empty tree.
#include "geometry/PointTree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace {

using isph::PointTree;
using isph::Vec3;

std::vector<Vec3> randomPoints(std::size_t n, bool plane, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < n; ++i) points.emplace_back(u(rng), u(rng), plane ? 0.0 : u(rng));
  return points;
}

long bruteNearest(const std::vector<Vec3>& points, const Vec3& x) {
  long best = -1;
  double bestSquared = 1e300;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d2 = (points[i] - x).squaredNorm();
    if (d2 < bestSquared) best = static_cast<long>(i), bestSquared = d2;
  }
  return best;
}

TEST(PointTree, NearestAndWithinAgreeWithALoopOverAllPoints) {
  for (const bool plane : {true, false}) {
    const auto points = randomPoints(1000, plane, 7);
    const PointTree tree(points);
    ASSERT_EQ(tree.size(), points.size());
    for (const Vec3& x : randomPoints(200, plane, 11)) {
      const Vec3 q = 1.5 * x;  // some queries outside the points' box
      EXPECT_EQ(tree.nearest(q), bruteNearest(points, q));
      std::vector<long> found = tree.within(q, 0.2), expected;
      for (std::size_t i = 0; i < points.size(); ++i) {
        if ((points[i] - q).norm() <= 0.2) expected.push_back(static_cast<long>(i));
      }
      std::sort(found.begin(), found.end());
      EXPECT_EQ(found, expected);
    }
  }
}

TEST(PointTree, TiesGoToTheLowestIndexAndFarQueriesFindTheNearest) {
  std::vector<Vec3> points;
  for (int i = 0; i < 40; ++i) points.emplace_back(0.01 * i, 0, 0);
  const PointTree tree(points);
  EXPECT_EQ(tree.nearest(Vec3(0.015, 1, 0)), 1);  // halfway between 1 and 2
  EXPECT_EQ(tree.nearest(Vec3(-100, -3, 0)), 0);
  EXPECT_EQ(tree.nearest(Vec3(100, 3, 0)), 39);
  EXPECT_EQ(tree.point(39), points[39]);
}

TEST(PointTree, AnEmptyTreeFindsNothing) {
  const PointTree tree;
  EXPECT_EQ(tree.nearest(Vec3::Zero()), -1);
  EXPECT_TRUE(tree.within(Vec3::Zero(), 1.0).empty());
  EXPECT_EQ(PointTree(std::vector<Vec3>{}).nearest(Vec3::Zero()), -1);
}

}  // namespace
