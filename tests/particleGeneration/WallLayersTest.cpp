// Walls: normals point into the domain, the layers fill the kernel support of every material
// particle near a wall (at straight walls and at concave and convex corners), no two particles
// are closer than dx/2, and material is removed from solids and from the wall clearance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "SceneTestHelpers.hpp"
#include "geometry/Box.hpp"
#include "geometry/Polygon.hpp"
#include "particleGeneration/SceneReader.hpp"
#include "particleGeneration/SpatialHash.hpp"

namespace isph {
namespace {

using test::addRegion;
using test::addWall;

// A tank (floor and two side walls as one polyline) holding a block, with a step in the
// floor and a solid barrier standing on it: concave and convex corners of every kind.
Scene tankScene(LatticeType lattice) {
  Scene s = test::emptyScene(0.01, lattice);
  s.wallLayers = 3;
  addRegion(s, "block", std::make_unique<Box>(Vec2(0, 0), Vec2(0.4, 0.3)), 1379);
  addRegion(s, "flow", std::make_unique<Box>(Vec2(0.45, -0.1), Vec2(1.15, 0.45)),
            1379);  // around the rest
  addWall(s, "tank", {{0, 0.5}, {0, 0}, {0.6, 0}, {0.6, -0.1}, {1.2, -0.1}, {1.2, 0.5}});
  addWall(s, "barrier", {{0.9, -0.1}, {0.95, -0.1}, {0.95, 0.2}, {0.9, 0.2}}, true);
  addWall(s, "wedge", {{0.7, 0.3}, {1.0, 0.33}, {0.75, 0.42}}, true);  // acute corners
  return s;
}

// The walls with the material (the block, around (0.2, 0.2)) on their left.
std::vector<WallSurface> materialOnTheLeft(const Scene& s) {
  std::vector<WallSurface> walls;
  for (const WallSpec& w : s.walls) {
    WallSurface surface = *w.surface;
    if (!surface.isClosed() && surface.distance(Vec2(0.2, 0.2)).signedDistance < 0) surface.flip();
    walls.push_back(surface);
  }
  return walls;
}

bool inAnySolid(const std::vector<WallSurface>& walls, const Vec2& x) {
  for (const WallSurface& w : walls) {
    if (w.inSolid(x)) return true;
  }
  return false;
}

class Walls : public ::testing::TestWithParam<LatticeType> {};

TEST_P(Walls, NormalsPointIntoTheDomain) {
  const Scene scene = tankScene(GetParam());
  const GenerationResult r = generateParticles(scene);
  const ParticleCloud& c = r.cloud;
  const std::vector<WallSurface> walls = materialOnTheLeft(scene);
  long nWall = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] != static_cast<label>(ParticleKind::wall)) {
      EXPECT_EQ(c.normal[i], Vec3::Zero());
      continue;
    }
    ++nWall;
    const Vec3& n = c.normal[i];
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    // Half a spacing along the normal is outside every solid; a little against it is inside
    // one (a little: the tip of the acute wedge is thinner than dx).
    const Vec2 x = toVec2(c.positions[i]);
    EXPECT_FALSE(inAnySolid(walls, x + 0.5 * scene.spacing * toVec2(n))) << "at " << x.transpose();
    EXPECT_TRUE(inAnySolid(walls, x - 0.05 * scene.spacing * toVec2(n))) << "at " << x.transpose();
  }
  EXPECT_GT(nWall, 0);
  // Wall particles on a face (not at a corner, where the normal is the mean of two) face
  // the material particles near them.
  std::vector<Vec2> corners;
  for (const WallSpec& w : scene.walls) {
    corners.insert(corners.end(), w.surface->chain().points().begin(),
                   w.surface->chain().points().end());
  }
  auto atCorner = [&](const Vec3& x) {
    return std::any_of(corners.begin(), corners.end(),
                       [&](const Vec2& v) { return (toVec2(x) - v).norm() < 1e-9; });
  };
  long checked = 0;
  for (std::size_t j = 0; j < c.size(); ++j) {
    if (c.kind[j] != static_cast<label>(ParticleKind::wall) || atCorner(c.positions[j])) continue;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const Vec3 d = c.positions[i] - c.positions[j];
      if (c.kind[i] != 0 || d.norm() > scene.spacing) continue;
      ++checked;
      EXPECT_GT(d.dot(c.normal[j]), 0.0) << "material at " << c.positions[i].transpose()
                                         << ", wall at " << c.positions[j].transpose();
    }
  }
  EXPECT_GT(checked, 100);
}

TEST_P(Walls, NoTwoParticlesCloserThanHalfASpacing) {
  const Scene scene = tankScene(GetParam());
  const GenerationResult r = generateParticles(scene);
  EXPECT_GE(r.closestPair, 0.5 * scene.spacing * (1 - 1e-9)) << r.closestPairKinds;
  SpatialHash hash(scene.spacing);
  for (const Vec3& x : r.cloud.positions) {
    EXPECT_FALSE(hash.anyCloserThan(toVec2(x), 0.5 * scene.spacing * (1 - 1e-9))) << x.transpose();
    hash.insert(toVec2(x));
  }
}

TEST_P(Walls, LayersFillTheKernelSupport) {
  const Scene scene = tankScene(GetParam());
  const GenerationResult r = generateParticles(scene);
  const ParticleCloud& c = r.cloud;
  const double dx = scene.spacing;
  const double support = 2.6 * dx;  // Wendland C2, h = 1.3 dx: 3 layers
  ASSERT_EQ(kernelWallLayers(support, dx), scene.wallLayers);

  // The solid, as material particles see it: behind any wall.
  const std::vector<WallSurface> walls = materialOnTheLeft(scene);
  SpatialHash solid(support);
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] != 0) solid.insert(toVec2(c.positions[i]));
  }
  long checked = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] != 0) continue;
    const Vec2 x = toVec2(c.positions[i]);
    if (!solid.anyCloserThan(x, support)) continue;
    // Every point of its support inside a solid has a wall or dummy particle nearby.
    for (double ox = -support; ox <= support; ox += 0.25 * dx) {
      for (double oy = -support; oy <= support; oy += 0.25 * dx) {
        const Vec2 y = x + Vec2(ox, oy);
        if (Vec2(ox, oy).norm() > support) continue;
        if (!inAnySolid(walls, y)) continue;
        ++checked;
        EXPECT_LT(solid.nearestDistance(y, support), 0.85 * dx)
            << "hole at " << y.transpose() << " in the support of " << x.transpose();
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

INSTANTIATE_TEST_SUITE_P(Lattices, Walls,
                         ::testing::Values(LatticeType::square, LatticeType::hexagonal));

TEST(Walls, StraightWallHasOneWallAndLayersMinusOneDummyLayers) {
  for (int layers : {3, 4}) {
    Scene s = test::emptyScene(0.1);
    s.wallLayers = layers;
    addRegion(s, "block", std::make_unique<Box>(Vec2(0, 0), Vec2(1, 0.5)));
    addWall(s, "bed", {{-1, 0}, {2, 0}});
    const GenerationResult r = generateParticles(s);
    EXPECT_EQ(test::countKind(r.cloud, ParticleKind::wall), 31);
    EXPECT_EQ(test::countKind(r.cloud, ParticleKind::dummy), 31 * (layers - 1));
    for (std::size_t i = 0; i < r.cloud.size(); ++i) {
      if (r.cloud.kind[i] == static_cast<label>(ParticleKind::material)) continue;
      const double depth = -r.cloud.positions[i].y() / 0.1;
      EXPECT_NEAR(depth, std::round(depth), 1e-9);
      EXPECT_LT(depth, layers - 0.5);
      EXPECT_EQ(r.cloud.patch[i], 0);
      EXPECT_EQ(r.cloud.material[i], -1);
      if (r.cloud.kind[i] == static_cast<label>(ParticleKind::wall)) {
        EXPECT_EQ(r.cloud.normal[i], Vec3(0, 1, 0));
      }
    }
  }
}

TEST(Walls, KernelLayers) {
  EXPECT_EQ(kernelWallLayers(2.6 * 0.01, 0.01), 3);  // h = 1.3 dx
  EXPECT_EQ(kernelWallLayers(3.0 * 0.01, 0.01), 3);  // h = 1.5 dx: exactly 3
  EXPECT_EQ(kernelWallLayers(4.0 * 0.01, 0.01), 4);  // h = 2 dx
}

TEST(Walls, ClearanceAndSolidsRemoveMaterial) {
  // A slope cutting through a block: sites behind it are in the solid, those within dx/2
  // in front of it are too close; the counts match a direct check.
  Scene s = test::emptyScene(0.01);
  addRegion(s, "block", std::make_unique<Box>(Vec2(0, 0), Vec2(1, 1)));
  addWall(s, "slope", {{-0.1, 0.05}, {1.1, 0.62}});
  addWall(s, "rock", {{0.6, 0.8}, {0.8, 0.8}, {0.8, 0.9}}, true);
  s.walls[0].side = MaterialSide::left;  // material above: the block lies on both sides
  const GenerationResult r = generateParticles(s);
  const Polyline slope({{-0.1, 0.05}, {1.1, 0.62}});
  const Polygon rock({{0.6, 0.8}, {0.8, 0.8}, {0.8, 0.9}});
  long behind = 0, near = 0, kept = 0;
  for (long j = 0; j < 100; ++j) {
    for (long i = 0; i < 100; ++i) {
      const Vec2 p((i + 0.5) * 0.01, (j + 0.5) * 0.01);
      const double d = slope.signedDistance(p).signedDistance;
      const double dr = rock.signedDistance(p);
      if (d < 0 || dr < 0) {
        ++behind;
      } else if (d < 0.005 * (1 - 1e-9) || dr < 0.005 * (1 - 1e-9)) {
        ++near;
      } else {
        ++kept;
      }
    }
  }
  EXPECT_EQ(r.regions[0].inSolid, behind);
  EXPECT_EQ(r.regions[0].nearWall, near);
  EXPECT_EQ(r.regions[0].particles, kept);
  EXPECT_EQ(test::countKind(r.cloud, ParticleKind::material), kept);
}

TEST(Walls, AutomaticSideNeedsMaterialNearby) {
  Scene s = test::emptyScene(0.01);
  addRegion(s, "block", std::make_unique<Box>(Vec2(0, 0), Vec2(0.2, 0.2)));
  addWall(s, "farFloor", {{5, 0}, {6, 0}});
  const FatalError e = test::expectFatal([&] { generateParticles(s); });
  EXPECT_NE(std::string(e.what()).find("materialSide"), std::string::npos) << e.what();
  s.walls[0].side = MaterialSide::right;  // material below: normals point down
  const GenerationResult r = generateParticles(s);
  for (std::size_t i = 0; i < r.cloud.size(); ++i) {
    if (r.cloud.kind[i] == static_cast<label>(ParticleKind::wall)) {
      EXPECT_EQ(r.cloud.normal[i], Vec3(0, -1, 0));
    }
  }
}

TEST(Walls, BarrierStandingOnABedCoversTheContact) {
  Scene s = test::emptyScene(0.01);
  addRegion(s, "sand", std::make_unique<Box>(Vec2(0, 0), Vec2(0.5, 0.2)));
  addWall(s, "bed", {{0, 0.3}, {0, 0}, {2, 0}});
  addWall(s, "barrier", {{1.0, 0}, {1.02, 0}, {1.02, 0.3}, {1.0, 0.3}}, true);
  const GenerationResult r = generateParticles(s);
  // No wall particle faces into the barrier from the bed under it.
  for (std::size_t i = 0; i < r.cloud.size(); ++i) {
    if (r.cloud.kind[i] != static_cast<label>(ParticleKind::wall)) continue;
    const Vec3& x = r.cloud.positions[i];
    if (x.x() > 1.0 + 1e-9 && x.x() < 1.02 - 1e-9 && std::abs(x.y()) < 1e-9)
      ADD_FAILURE() << "bed surface under the barrier";
  }
  EXPECT_GT(r.walls[0].stats.demoted, 0);
}

// A barrier foot ten spacings wide (the flagship's 20 mm barrier at 1.8 mm): the bed's
// particles under its middle are further than the layers from every wall particle, out of
// every material particle's support, and the solver could not give them a wall to take their
// pressure from; they are dropped, and every dummy kept has a wall particle within
// (layers + 1/2) dx.
TEST(Walls, AWideBarrierFootKeepsNoDummyOutOfReachOfTheWallParticles) {
  const double dx = 0.01;
  Scene s = test::emptyScene(dx);
  addRegion(s, "sand", std::make_unique<Box>(Vec2(0, 0), Vec2(0.5, 0.2)));
  addWall(s, "bed", {{0, 0.3}, {0, 0}, {2, 0}});
  addWall(s, "barrier", {{1.0, 0}, {1.1, 0}, {1.1, 0.3}, {1.0, 0.3}}, true);
  const GenerationResult r = generateParticles(s);
  const ParticleCloud& c = r.cloud;
  const auto wall = static_cast<label>(ParticleKind::wall), dummy = static_cast<label>(ParticleKind::dummy);
  const double reach = (s.wallLayers + 0.5) * dx;
  long dummies = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] != dummy) continue;
    ++dummies;
    double nearest = 1e9;
    for (std::size_t j = 0; j < c.size(); ++j)
      if (c.kind[j] == wall) nearest = std::min(nearest, (c.positions[j] - c.positions[i]).norm());
    EXPECT_LT(nearest, reach) << "dummy at " << c.positions[i].transpose();
  }
  EXPECT_GT(dummies, 0);
  // Under the middle of the foot (1.04 < x < 1.06) nothing is left; near its faces the
  // bed's layers are kept.
  long middle = 0, nearFaces = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Vec3& x = c.positions[i];
    if (c.kind[i] == dummy && x.y() <= 1e-9 && x.x() > 1.04 && x.x() < 1.06) ++middle;
    if (c.kind[i] == dummy && x.y() <= 1e-9 && x.x() > 1.0 && x.x() < 1.02) ++nearFaces;
  }
  EXPECT_EQ(middle, 0);
  EXPECT_GT(nearFaces, 0);
  EXPECT_GT(r.walls[0].stats.dropped, 0);
}

}  // namespace
}  // namespace isph
