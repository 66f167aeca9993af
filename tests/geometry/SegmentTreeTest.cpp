// SegmentTree: the nearest segment equals a brute-force search, on a long random chain.
#include <gtest/gtest.h>

#include <random>

#include "geometry/Segment.hpp"
#include "geometry/SegmentTree.hpp"

namespace isph {
namespace {

TEST(SegmentTree, NearestMatchesBruteForce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec2> a, b;
  Vec2 p(0, 0);
  for (int i = 0; i < 500; ++i) {
    const Vec2 q = p + Vec2(0.1 + 0.05 * u(rng), 0.1 * u(rng));
    a.push_back(p);
    b.push_back(q);
    p = q;
  }
  const SegmentTree tree(a, b);
  for (int k = 0; k < 2000; ++k) {
    const Vec2 x(30 * u(rng) + 25, 5 * u(rng));
    double best = 1e300;
    for (std::size_t s = 0; s < a.size(); ++s)
      best = std::min(best, distanceSquared(a[s], b[s], x));
    const auto hit = tree.nearest(x);
    EXPECT_DOUBLE_EQ(hit.distanceSquared, best);
    EXPECT_NEAR((hit.point - x).squaredNorm(), best, 1e-12);
  }
}

TEST(SegmentTree, EmptyTreeHasNoHit) { EXPECT_EQ(SegmentTree().nearest(Vec2(0, 0)).segment, -1); }

}  // namespace
}  // namespace isph
