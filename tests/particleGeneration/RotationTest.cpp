// A rotated scene gives the same counts as the unrotated one: with a `transform` exactly (the
// particles are generated in the scene frame and then moved), and with the geometry itself
// rotated on the lattice within 1%.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "SceneTestHelpers.hpp"
#include "geometry/Box.hpp"
#include "geometry/Polygon.hpp"

namespace isph {
namespace {

using test::addRegion;
using test::addWall;
using test::countKind;

Vec2 rotated(const Vec2& p, double degrees) {
  const double a = degrees * std::numbers::pi / 180;
  return {std::cos(a) * p.x() - std::sin(a) * p.y(), std::sin(a) * p.x() + std::cos(a) * p.y()};
}

// A flume in slope-aligned coordinates: a block behind a back wall on a bed, and a barrier.
Scene flume(double rotate, const Vec2& origin, const Vec2& translate) {
  Scene s = test::emptyScene(0.01);
  s.transform = Transform(rotate, toVec3(origin), toVec3(translate));
  addRegion(s, "block", std::make_unique<Box>(Vec2(0, 0), Vec2(0.5, 0.24)), 1379);
  addWall(s, "bed", {{0, 0.4}, {0, 0}, {2.4, 0}});
  addWall(s, "barrier", {{1.8, 0}, {1.82, 0}, {1.82, 0.3}, {1.8, 0.3}}, true);
  s.initialPressure = InitialPressure::lithostatic;
  // Gravity in the case frame: along -y of the tilted flume's case frame.
  s.gravity = toVec3(rotated(Vec2(0, -9.81), rotate));
  return s;
}

TEST(Rotation, TransformedSceneMatchesTheUnrotatedOne) {
  const GenerationResult a = generateParticles(flume(0, {0, 0}, {0, 0}));
  const Scene tilted = flume(-30, {0.3, 0.1}, {1, 2});
  const GenerationResult b = generateParticles(tilted);
  ASSERT_EQ(a.cloud.size(), b.cloud.size());
  for (ParticleKind k : {ParticleKind::material, ParticleKind::wall, ParticleKind::dummy}) {
    EXPECT_EQ(countKind(a.cloud, k), countKind(b.cloud, k));
  }
  for (std::size_t i = 0; i < a.cloud.size(); ++i) {
    const Vec3 expected = tilted.transform.point(a.cloud.positions[i]);
    EXPECT_NEAR((b.cloud.positions[i] - expected).norm(), 0, 1e-12);
    EXPECT_NEAR((b.cloud.normal[i] - tilted.transform.vector(a.cloud.normal[i])).norm(), 0, 1e-12);
    EXPECT_NEAR(b.cloud.p[i], a.cloud.p[i], 1e-9 * (1 + a.cloud.p[i]));
    EXPECT_EQ(a.cloud.kind[i], b.cloud.kind[i]);
  }
}

TEST(Rotation, RotatedGeometryOnTheLatticeKeepsCountsWithinOnePercent) {
  const std::vector<Vec2> outline{{0, 0}, {0.8, 0}, {0.8, 0.3}, {0.3, 0.6}, {0, 0.6}};
  for (LatticeType lattice : {LatticeType::square, LatticeType::hexagonal}) {
    for (double angle : {17.0, 30.0, 45.0, -63.0}) {
      Scene a = test::emptyScene(0.005, lattice);
      addRegion(a, "shape", std::make_unique<Polygon>(outline));
      Scene b = test::emptyScene(0.005, lattice);
      std::vector<Vec2> turned;
      for (const Vec2& p : outline) turned.push_back(rotated(p, angle));
      addRegion(b, "shape", std::make_unique<Polygon>(turned));
      const double na = static_cast<double>(generateParticles(a).cloud.size());
      const double nb = static_cast<double>(generateParticles(b).cloud.size());
      EXPECT_NEAR(nb / na, 1.0, 0.01) << toString(lattice) << " " << angle << "°";
    }
  }
}

}  // namespace
}  // namespace isph
