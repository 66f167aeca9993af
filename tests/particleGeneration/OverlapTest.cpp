// Overlapping regions: the first listed wins, the later one counts its lost sites per
// earlier region, and no site is given twice.
#include <gtest/gtest.h>

#include <set>

#include "SceneTestHelpers.hpp"
#include "geometry/Box.hpp"
#include "geometry/Polygon.hpp"
#include "particleGeneration/RegionFilling.hpp"

namespace isph {
namespace {

TEST(Overlap, FirstListedWins) {
  Scene scene = test::emptyScene(0.01);
  test::addRegion(scene, "a", std::make_unique<Box>(Vec2(0, 0), Vec2(1, 1)), 1000, 0);
  test::addRegion(scene, "b", std::make_unique<Box>(Vec2(0.5, 0), Vec2(1.5, 1)), 2000, 1);
  const GenerationResult r = generateParticles(scene);
  ASSERT_EQ(r.regions.size(), 2u);
  EXPECT_EQ(r.regions[0].particles, 10000);
  EXPECT_EQ(r.regions[1].inside, 10000);
  EXPECT_EQ(r.regions[1].particles, 5000);
  ASSERT_EQ(r.regions[1].lostTo.size(), 1u);
  EXPECT_EQ(r.regions[1].lostTo[0].first, "a");
  EXPECT_EQ(r.regions[1].lostTo[0].second, 5000);
  for (std::size_t i = 0; i < r.cloud.size(); ++i) {
    if (r.cloud.positions[i].x() < 1) {
      EXPECT_EQ(r.cloud.material[i], 0);
    }
  }
}

TEST(Overlap, LostSitesArePerEarlierRegionAndNoSiteTwice) {
  const Lattice lattice(LatticeType::hexagonal, 0.02);
  const Box a(Vec2(0, 0), Vec2(1, 1));
  const Box b(Vec2(0.8, 0), Vec2(2, 1));
  const Polygon c({{0.5, 0.5}, {1.5, 0.5}, {1.0, 1.5}});
  const auto sites = fillRegions({&a, &b, &c}, lattice);
  ASSERT_EQ(sites[2].lostTo.size(), 2u);
  // Brute force: sites of c inside a, and inside b but not a.
  long inA = 0, inB = 0, inC = 0;
  for (long j = -5; j < 120; ++j) {
    for (long i = -5; i < 120; ++i) {
      const Vec3 p = toVec3(lattice.site(i, j));
      if (!c.contains(p)) continue;
      ++inC;
      if (a.contains(p)) {
        ++inA;
      } else if (b.contains(p)) {
        ++inB;
      }
    }
  }
  EXPECT_EQ(sites[2].inside, inC);
  EXPECT_EQ(sites[2].lostTo[0], inA);
  EXPECT_EQ(sites[2].lostTo[1], inB);
  EXPECT_EQ(static_cast<long>(sites[2].sites.size()), inC - inA - inB);
  std::set<std::pair<long, long>> seen;
  for (const auto& region : sites) {
    for (const Vec2& s : region.sites) {
      EXPECT_TRUE(seen.insert({std::lround(s.x() / 0.001), std::lround(s.y() / 0.001)}).second)
          << s.transpose();
    }
  }
}

}  // namespace
}  // namespace isph
