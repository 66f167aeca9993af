// Lithostatic initial pressure: ρ|g| times the depth below the free surface along g, for
// layers of different density, on both lattices and for a tilted scene; zero by default.
#include <gtest/gtest.h>

#include "SceneTestHelpers.hpp"
#include "geometry/Box.hpp"
#include "geometry/Polygon.hpp"
#include "particleGeneration/LithostaticPressure.hpp"

namespace isph {
namespace {

TEST(Lithostatic, ZeroUnlessAsked) {
  Scene s = test::emptyScene(0.1);
  test::addRegion(s, "block", std::make_unique<Box>(Vec2(0, 0), Vec2(1, 1)));
  for (double p : generateParticles(s).cloud.p) EXPECT_EQ(p, 0.0);
}

TEST(Lithostatic, TopRowCarriesHalfACell) {
  for (LatticeType lattice : {LatticeType::square, LatticeType::hexagonal}) {
    Scene s = test::emptyScene(0.1, lattice);
    test::addRegion(s, "block", std::make_unique<Box>(Vec2(0, 0), Vec2(1, 0.5)), 2000);
    s.initialPressure = InitialPressure::lithostatic;
    s.gravity = Vec3(0, -10, 0);
    const ParticleCloud c = generateParticles(s).cloud;
    for (std::size_t i = 0; i < c.size(); ++i) {
      EXPECT_NEAR(c.p[i], 2000 * 10 * (0.5 - c.positions[i].y()), 1e-9) << toString(lattice);
    }
  }
}

TEST(Lithostatic, LayersOfDifferentDensityAddUp) {
  // Clay (1800) from 0 to 0.3 under sand (1400) from 0.3 to 0.5; an air gap, then a second
  // sand block above part of it counts as well (an overhang).
  Scene s = test::emptyScene(0.05);
  test::addRegion(s, "sand", std::make_unique<Box>(Vec2(0, 0.3), Vec2(1, 0.5)), 1400);
  test::addRegion(s, "clay", std::make_unique<Box>(Vec2(0, 0), Vec2(1, 0.3)), 1800, 1);
  test::addRegion(s, "shelf", std::make_unique<Box>(Vec2(0, 0.7), Vec2(0.5, 0.8)), 1400);
  s.initialPressure = InitialPressure::lithostatic;
  s.gravity = Vec3(0, -9.81, 0);
  const ParticleCloud c = generateParticles(s).cloud;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double x = c.positions[i].x(), y = c.positions[i].y();
    double expected = 0;
    if (y > 0.7) {
      expected = 1400 * (0.8 - y);
    } else if (y > 0.3) {
      expected = 1400 * (0.5 - y);
    } else {
      expected = 1400 * 0.2 + 1800 * (0.3 - y);
    }
    if (x < 0.5 && y < 0.7) expected += 1400 * 0.1;
    EXPECT_NEAR(c.p[i], 9.81 * expected, 1e-8) << x << " " << y;
  }
}

TEST(Lithostatic, AlongATiltedGravity) {
  // The column above each point is measured along g, not along the lattice.
  const Box block(Vec2(0, 0), Vec2(1, 1));
  const std::vector<const Region*> regions{&block};
  const Vec2 up = Vec2(1, 2).normalized();
  const auto p = lithostaticPressure({{0.5, 0.5}, {0.9, 0.1}}, regions, {1000}, up, 10);
  // From (0.5, 0.5) along (1, 2): leaves through y = 1 after t = 0.5 / (2/√5).
  EXPECT_NEAR(p[0], 1000 * 10 * 0.5 * std::sqrt(5.0) / 2, 1e-9);
  // From (0.9, 0.1): leaves through x = 1 after t = 0.1 / (1/√5).
  EXPECT_NEAR(p[1], 1000 * 10 * 0.1 * std::sqrt(5.0), 1e-9);
}

}  // namespace
}  // namespace isph
