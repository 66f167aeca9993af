// Counts: a box, a triangle and a slanted polygon hold area/dx² sites (area / site area)
// within 1% on square and hexagonal lattices; mass per material is area × ρ within 1%.
#include <gtest/gtest.h>

#include <cmath>

#include "SceneTestHelpers.hpp"
#include "geometry/Box.hpp"
#include "geometry/Polygon.hpp"
#include "particleGeneration/Lattice.hpp"

namespace isph {
namespace {

using test::addRegion;
using test::emptyScene;

std::unique_ptr<Region> shape(const std::string& name) {
  if (name == "box") return std::make_unique<Box>(Vec2(0.013, -0.2), Vec2(1.013, 0.4));
  if (name == "triangle")
    return std::make_unique<Polygon>(std::vector<Vec2>{{0, 0}, {1, 0.1}, {0.3, 0.9}});
  // A parallelogram tilted by 20°, given clockwise.
  const double c = std::cos(0.349), s = std::sin(0.349);
  return std::make_unique<Polygon>(
      std::vector<Vec2>{{0.1, 0.05},
                        {0.1 - 0.5 * s, 0.05 + 0.5 * c},
                        {0.1 + 0.9 * c - 0.5 * s, 0.05 + 0.9 * s + 0.5 * c},
                        {0.1 + 0.9 * c, 0.05 + 0.9 * s}});
}

class LatticeCount : public ::testing::TestWithParam<std::tuple<const char*, LatticeType>> {};

TEST_P(LatticeCount, AreaOverSiteAreaWithinOnePercent) {
  const auto [name, lattice] = GetParam();
  const double dx = 0.01;
  Scene scene = emptyScene(dx, lattice);
  addRegion(scene, name, shape(name), 1379);
  const GenerationResult r = generateParticles(scene);
  const double area = scene.regions[0].shape->measure();
  const double siteArea = Lattice(lattice, dx).siteArea();
  const double n = static_cast<double>(r.cloud.size());
  EXPECT_NEAR(n * siteArea / area, 1.0, 0.01)
      << name << " " << toString(lattice) << ": " << n << " sites";
  EXPECT_NEAR(r.regions[0].mass / (area * 1379), 1.0, 0.01);
  for (double m : r.cloud.mass) EXPECT_DOUBLE_EQ(m, 1379 * siteArea);
}

INSTANTIATE_TEST_SUITE_P(Shapes, LatticeCount,
                         ::testing::Combine(::testing::Values("box", "triangle", "slanted"),
                                            ::testing::Values(LatticeType::square,
                                                              LatticeType::hexagonal)));

TEST(LatticeCount, SiteAreas) {
  EXPECT_DOUBLE_EQ(Lattice(LatticeType::square, 0.1).siteArea(), 0.01);
  EXPECT_NEAR(Lattice(LatticeType::hexagonal, 0.1).siteArea(), 0.5 * std::sqrt(3.0) * 0.01, 1e-15);
  // Hexagonal: six neighbours at dx.
  const Lattice hex(LatticeType::hexagonal, 1.0);
  EXPECT_NEAR((hex.site(0, 1) - hex.site(0, 0)).norm(), 1.0, 1e-12);
  EXPECT_NEAR((hex.site(0, 1) - hex.site(1, 0)).norm(), 1.0, 1e-12);
  EXPECT_NEAR((hex.site(1, 0) - hex.site(0, 0)).norm(), 1.0, 1e-12);
}

TEST(LatticeCount, BoxOnCellFacesHoldsWholeCells) {
  Scene scene = emptyScene(0.1);
  addRegion(scene, "b", std::make_unique<Box>(Vec2(0, 0), Vec2(1, 0.5)));
  const GenerationResult r = generateParticles(scene);
  EXPECT_EQ(r.cloud.size(), 50u);
  EXPECT_NEAR(r.cloud.positions.front().x(), 0.05, 1e-15);
  EXPECT_NEAR(r.cloud.positions.front().y(), 0.05, 1e-15);
}

TEST(LatticeCount, MassPerMaterialIsAreaTimesDensity) {
  const double dx = 0.005;
  for (LatticeType lattice : {LatticeType::square, LatticeType::hexagonal}) {
    Scene scene = emptyScene(dx, lattice);
    addRegion(scene, "sandBox", std::make_unique<Box>(Vec2(0, 0), Vec2(0.5, 0.3)), 1379, 0);
    addRegion(scene, "clayWedge",
              std::make_unique<Polygon>(std::vector<Vec2>{{0.6, 0}, {1.2, 0}, {0.6, 0.4}}), 1800,
              1);
    addRegion(scene, "sandTop", std::make_unique<Box>(Vec2(0, 0.4), Vec2(0.4, 0.6)), 1379, 0);
    const GenerationResult r = generateParticles(scene);
    double mass[2] = {0, 0};
    for (std::size_t i = 0; i < r.cloud.size(); ++i) mass[r.cloud.material[i]] += r.cloud.mass[i];
    EXPECT_NEAR(mass[0] / ((0.15 + 0.08) * 1379), 1.0, 0.01) << toString(lattice);
    EXPECT_NEAR(mass[1] / (0.12 * 1800), 1.0, 0.01) << toString(lattice);
    // origId is 0..N-1 in order.
    for (std::size_t i = 0; i < r.cloud.size(); ++i)
      EXPECT_EQ(r.cloud.origId[i], static_cast<label>(i));
  }
}

TEST(LatticeCount, RegionWithoutSitesIsAnError) {
  Scene scene = emptyScene(0.1);
  addRegion(scene, "sliver", std::make_unique<Box>(Vec2(0.01, 0.01), Vec2(0.04, 0.04)));
  const FatalError e = test::expectFatal([&] { generateParticles(scene); });
  EXPECT_NE(std::string(e.what()).find("region 'sliver'"), std::string::npos) << e.what();
  EXPECT_NE(std::string(e.what()).find("holds no lattice site"), std::string::npos);
}

}  // namespace
}  // namespace isph
