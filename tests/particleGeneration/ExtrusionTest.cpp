// A 3D scene is its x-y section extruded along z (Extrusion.hpp): an open tank of water 0.4 ×
// 0.3 m, walls left, right and below, 0.2 m wide, at dx = 0.05 (4 layers). Checked against
// the 2D scene of the same section: every layer holds the section's particles, masses are
// ρ dx³, the side walls close the ends with wall particles facing the material and dummies
// behind. (That they hold water at rest with the exact pressure and wall force is the
// tutorial hydrostaticTank3D's check.)
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "SceneTestHelpers.hpp"
#include "geometry/Box.hpp"
#include "geometry/Cylinder.hpp"
#include "particleGeneration/Extrusion.hpp"

namespace isph {
namespace {

using test::addRegion;
using test::addWall;
using test::countKind;
using test::emptyScene;

constexpr double dx = 0.05, rho = 1000;

Scene tank(int dimension, bool sideWalls) {
  Scene s = emptyScene(dx);
  s.dimension = dimension;
  s.width = dimension == 3 ? 0.2 : 0.0;
  s.initialPressure = InitialPressure::lithostatic;
  s.gravity = Vec3(0, -9.81, 0);
  addRegion(s, "water", std::make_unique<Box>(Vec2(0, 0), Vec2(0.4, 0.3)), rho);
  addWall(s, "left", {{0, 0.4}, {0, 0}});
  addWall(s, "right", {{0.4, 0}, {0.4, 0.4}});
  addWall(s, "bottom", {{0, 0}, {0.4, 0}});
  if (sideWalls) {
    s.patches.push_back({"sides", 25.0});
    s.sideWalls = SideWallSpec{.patch = {1, 1}, .density = rho, .where = {}};
  }
  return s;
}

std::vector<std::size_t> ofKind(const ParticleCloud& c, ParticleKind k) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c.kind[i] == static_cast<label>(k)) out.push_back(i);
  return out;
}

// x-y positions (rounded to 1e-9 m) of the particles of one kind and patch in a cloud.
std::multiset<std::pair<long, long>> section(const ParticleCloud& c, ParticleKind k, double z) {
  std::multiset<std::pair<long, long>> out;
  for (std::size_t i : ofKind(c, k)) {
    if (c.patch[i] == 1 || std::abs(c.positions[i].z() - z) > 1e-12) continue;
    out.emplace(std::lround(c.positions[i].x() * 1e9), std::lround(c.positions[i].y() * 1e9));
  }
  return out;
}

TEST(Extrusion, EveryLayerHoldsTheSection) {
  const GenerationResult flat = generateParticles(tank(2, false));
  const GenerationResult slab = generateParticles(tank(3, true));
  EXPECT_EQ(slab.cloud.properties.dimension, 3);
  const std::vector<double> layers = extrusionLayers(tank(3, true));
  ASSERT_EQ(layers.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(layers[k], (k + 0.5) * dx, 1e-15);
  const std::size_t nFlat = ofKind(flat.cloud, ParticleKind::material).size();
  ASSERT_EQ(ofKind(slab.cloud, ParticleKind::material).size(), 4 * nFlat);
  for (const double z : extrusionLayers(tank(3, true))) {
    for (const ParticleKind k : {ParticleKind::material, ParticleKind::wall, ParticleKind::dummy})
      EXPECT_EQ(section(slab.cloud, k, z), section(flat.cloud, k, 0.0)) << "z = " << z;
  }
  // Material: ρ dx³ each, ρ V in all, p = ρ g (H - y) as in 2D.
  double mass = 0;
  for (std::size_t i : ofKind(slab.cloud, ParticleKind::material)) {
    EXPECT_DOUBLE_EQ(slab.cloud.mass[i], rho * dx * dx * dx);
    EXPECT_NEAR(slab.cloud.p[i], rho * 9.81 * (0.3 - slab.cloud.positions[i].y()), 1e-9);
    mass += slab.cloud.mass[i];
  }
  EXPECT_NEAR(mass, rho * 0.4 * 0.3 * 0.2, 1e-9);
  EXPECT_NEAR(slab.regions[0].mass, rho * 0.4 * 0.3 * 0.2, 1e-9);
  for (std::size_t i : ofKind(slab.cloud, ParticleKind::wall)) {
    if (slab.cloud.patch[i] != 1) {
      EXPECT_EQ(slab.cloud.normal[i].z(), 0.0);
    }
    EXPECT_DOUBLE_EQ(slab.cloud.mass[i], rho * dx * dx * dx);
  }
}

// `zRange` (ZSlabs.hpp): water over part of the width, and a second region over the rest.
// Each fills exactly the layers whose z lies in its range, with the section it has alone; the
// walls span the width; the particles are the 2D section's in each layer.
TEST(Extrusion, ARegionFillsTheLayersOfItsZRange) {
  Scene s = tank(3, true);
  s.regions[0].zRange = ZRange{0.0, 0.1, {}};  // layers 0.025, 0.075
  addRegion(s, "rest", std::make_unique<Box>(Vec2(0, 0), Vec2(0.4, 0.15)), 2 * rho);
  s.regions[1].zRange = ZRange{0.1, 0.2, {}};  // layers 0.125, 0.175: half the depth
  const GenerationResult r = generateParticles(s);
  const GenerationResult flat = generateParticles(tank(2, false));
  const auto flatWater = section(flat.cloud, ParticleKind::material, 0.0);
  std::size_t lowSites = 0;
  for (const auto& [x, y] : flatWater) lowSites += y < 0.15e9 ? 1 : 0;
  ASSERT_GT(lowSites, 0u);
  for (const double z : extrusionLayers(s)) {
    const auto here = section(r.cloud, ParticleKind::material, z);
    if (z < 0.1) {
      EXPECT_EQ(here, flatWater) << "z = " << z;
    } else {
      EXPECT_EQ(here.size(), lowSites) << "z = " << z;
    }
    EXPECT_EQ(section(r.cloud, ParticleKind::wall, z), section(flat.cloud, ParticleKind::wall, 0.0)) << "z = " << z;
  }
  ASSERT_EQ(r.regions.size(), 2u);
  EXPECT_EQ(r.regions[0].particles, static_cast<long>(2 * flatWater.size()));
  EXPECT_EQ(r.regions[1].particles, static_cast<long>(2 * lowSites));
  EXPECT_NEAR(r.regions[0].mass, rho * 0.4 * 0.3 * 0.1, 1e-9);
  EXPECT_NEAR(r.regions[1].mass, 2 * rho * 0.4 * 0.15 * 0.1, 1e-9);
  EXPECT_NEAR(r.regions[1].geometricArea, 0.4 * 0.15 * 0.1, 1e-12);
  // Material particles in cloud order: water (both its layers) first, then the rest.
  for (std::size_t i = 0; i < r.cloud.size(); ++i) {
    if (r.cloud.kind[i] != static_cast<label>(ParticleKind::material)) continue;
    const bool water = i < static_cast<std::size_t>(r.regions[0].particles);
    EXPECT_EQ(r.cloud.positions[i].z() < 0.1, water) << i;
    // p = rho g (H - y) with each column's own height and density
    const double H = water ? 0.3 : 0.15, density = water ? rho : 2 * rho;
    EXPECT_NEAR(r.cloud.p[i], density * 9.81 * (H - r.cloud.positions[i].y()), 1e-9) << i;
  }
}

// A 3D region (Cylinder.hpp) is cut, not extruded: each layer holds the lattice sites of its
// section, so the particles are exactly the cubic lattice's sites inside the cylinder (radius
// 0.125 m, 0.2 m high, on a bed; 2.5 and 5 spacings of radius). Their volume against π R² H
// is the staircase circle's: 0.815 and 1.019 here.
TEST(Extrusion, ACylinderFillsItsSectionInEachLayer) {
  for (const double spacing : {0.05, 0.025}) {
    Scene s = emptyScene(spacing);
    s.dimension = 3;
    s.width = 0.4;
    const Vec3 base(0.2, 0, 0.2);
    addRegion(s, "column", std::make_unique<Cylinder>(base, 0.125, 0.2), rho);
    addWall(s, "bed", {{-0.1, 0}, {0.5, 0}});
    const GenerationResult r = generateParticles(s);
    long expected = 0;  // the cubic lattice's sites inside the cylinder
    for (long k = 0; k < std::lround(0.4 / spacing); ++k) {
      for (long i = 0; i < std::lround(0.4 / spacing); ++i) {
        for (long j = 0; j < std::lround(0.2 / spacing); ++j) {
          expected += Cylinder(base, 0.125, 0.2).contains(Vec3((i + 0.5) * spacing, (j + 0.5) * spacing,
                                                               (k + 0.5) * spacing))
                          ? 1
                          : 0;
        }
      }
    }
    ASSERT_EQ(r.regions[0].particles, expected) << "dx = " << spacing;
    for (std::size_t i = 0; i < r.cloud.size(); ++i) {
      if (r.cloud.kind[i] != static_cast<label>(ParticleKind::material)) continue;
      EXPECT_TRUE(Cylinder(base, 0.125, 0.2).contains(r.cloud.positions[i])) << i;
      EXPECT_DOUBLE_EQ(r.cloud.mass[i], rho * spacing * spacing * spacing);
    }
    const double volume = M_PI * 0.125 * 0.125 * 0.2;
    EXPECT_DOUBLE_EQ(r.regions[0].geometricArea, volume);
  }
}

TEST(Extrusion, SideWallsCloseTheEnds) {
  const Scene scene = tank(3, true);
  const GenerationResult r = generateParticles(scene);
  const ParticleCloud& c = r.cloud;
  long walls[2] = {0, 0};
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.patch[i] != 1) continue;
    const Vec3& x = c.positions[i];
    const bool near = x.z() < 0.1;
    const double depth = near ? -x.z() : x.z() - 0.2;  // behind the side wall's surface
    EXPECT_GE(depth, -1e-12) << "side-wall particle in the material's span";
    EXPECT_LT(depth, scene.wallLayers * dx);
    const bool inSection = x.x() > 0 && x.x() < 0.4 && x.y() > 0;
    if (c.kind[i] == static_cast<label>(ParticleKind::wall)) {
      ++walls[near ? 0 : 1];
      EXPECT_NEAR(depth, 0.0, 1e-12);
      EXPECT_EQ(c.normal[i], Vec3(0, 0, near ? 1 : -1));
      EXPECT_TRUE(inSection) << "a side-wall surface particle behind the tank's walls";
    } else {
      EXPECT_TRUE(depth > 0.5 * dx || !inSection);
    }
  }
  // One wall particle per lattice site of the tank's inside, at each end (up to the walls'
  // top at 0.4 m: 8 columns, 8 rows).
  EXPECT_EQ(walls[0], 64);
  EXPECT_EQ(walls[1], 64);
  EXPECT_DOUBLE_EQ(r.closestPair, 0.5 * dx);

  // Without side walls the ends are open: nothing beyond 0 <= z <= width.
  for (const Vec3& x : generateParticles(tank(3, false)).cloud.positions) {
    EXPECT_GT(x.z(), 0.0);
    EXPECT_LT(x.z(), 0.2);
  }
}

// The side walls' `max (x y 0)`: they cover the section up to y = 0.3 only (the water's top),
// 6 rows of wall particles at each end instead of 8, nothing above; the rest is unchanged.
TEST(Extrusion, SideWallsCoverTheirExtentOnly) {
  Scene s = tank(3, true);
  s.sideWalls->max = Vec2(1e300, 0.3);
  const GenerationResult clipped = generateParticles(s);
  const GenerationResult full = generateParticles(tank(3, true));
  long walls[2] = {0, 0}, dummies = 0, fullDummies = 0;
  for (std::size_t i = 0; i < clipped.cloud.size(); ++i) {
    if (clipped.cloud.patch[i] != 1) continue;
    EXPECT_LE(clipped.cloud.positions[i].y(), 0.3 + 1e-12);
    if (clipped.cloud.kind[i] == static_cast<label>(ParticleKind::wall))
      ++walls[clipped.cloud.positions[i].z() > 0.1 ? 1 : 0];
    else
      ++dummies;
  }
  for (std::size_t i = 0; i < full.cloud.size(); ++i) {
    if (full.cloud.patch[i] == 1 && full.cloud.kind[i] == static_cast<label>(ParticleKind::dummy)) ++fullDummies;
  }
  EXPECT_EQ(walls[0], 48);
  EXPECT_EQ(walls[1], 48);
  EXPECT_LT(dummies, fullDummies);
  for (const ParticleKind k : {ParticleKind::material, ParticleKind::wall, ParticleKind::dummy}) {
    for (const double z : extrusionLayers(s))
      EXPECT_EQ(section(clipped.cloud, k, z), section(full.cloud, k, z)) << "z = " << z;
  }
}

}  // namespace
}  // namespace isph
