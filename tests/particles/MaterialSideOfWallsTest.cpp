// MaterialSideOfWalls (particles/MaterialSideOfWalls.hpp) on wall particles laid out as
// particleMesh lays them (one every dx on the surface, normals towards the material):
//  - an open tank (left wall x = 0 owning the bottom corner with its normal (1 0), bed y = 0
//    from dx, right wall x = 0.4), the walls of tutorials' hydrostaticTank: water inside is on
//    the material side; below the bed, beside the corners and behind the side walls is behind a
//    wall, with the depth and the nearest wall particle; beside the walls' open tops, on their
//    solid side, is past an open end; above the tops on the material side is material;
//  - the corner subtlety: a point below the bed a tenth of dx right of the corner has the
//    corner particle nearest, whose normal (1 0) alone calls it water;
//  - a solid block (material all round): beside its corners is material, inside it is behind;
//  - the same block in 3D (its section extruded at z = (k + 1/2) dx) standing against a side
//    wall at z = 0 (wall particles on the material's lattice outside the block, as particleMesh
//    puts them): water above the block by the side wall is material, as are the points beside
//    its faces; inside it and behind the side wall is behind (before, the block's side face
//    was taken for a wedge with the side wall and the water above the block was behind);
//  - ofCloud takes the wall particles only (a dummy behind the wall is not a wall).
#include "particles/MaterialSideOfWalls.hpp"

#include <gtest/gtest.h>

#include "particles/ParticleCloud.hpp"

namespace {

using isph::MaterialSideOfWalls;
using isph::Vec3;
using Side = MaterialSideOfWalls::Side;

constexpr double dx = 0.01;

// Patches: 0 left, 1 bed, 2 right.
std::vector<MaterialSideOfWalls::WallPoint> openTank() {
  std::vector<MaterialSideOfWalls::WallPoint> w;
  for (int j = 0; j <= 50; ++j) w.push_back({Vec3(0, j * dx, 0), Vec3(1, 0, 0), 0});
  for (int i = 1; i < 40; ++i) w.push_back({Vec3(i * dx, 0, 0), Vec3(0, 1, 0), 1});
  for (int j = 0; j <= 50; ++j) w.push_back({Vec3(0.4, j * dx, 0), Vec3(-1, 0, 0), 2});
  return w;
}

Side sideOf(const MaterialSideOfWalls& s, double x, double y) { return s.classify(Vec3(x, y, 0)).side; }

TEST(MaterialSideOfWalls, WaterInsideAnOpenTankIsOnTheMaterialSide) {
  const MaterialSideOfWalls s(openTank(), dx);
  for (const double x : {0.5 * dx, 0.1, 0.2, 0.4 - 0.5 * dx}) {
    for (const double y : {0.5 * dx, 0.1, 0.399, 0.6}) EXPECT_EQ(sideOf(s, x, y), Side::material) << x << " " << y;
  }
  EXPECT_EQ(sideOf(s, 0, 0.2), Side::material);  // on the surface
}

TEST(MaterialSideOfWalls, BelowTheBedBesideTheCornersAndBehindTheSideWallsIsBehindAWall) {
  const MaterialSideOfWalls s(openTank(), dx);
  const auto below = s.classify(Vec3(0.2, -0.05, 0));
  EXPECT_EQ(below.side, Side::behindWall);
  EXPECT_NEAR(below.depth, -0.05, 1e-12);
  EXPECT_EQ(s.walls()[static_cast<std::size_t>(below.wall)].patch, 1);
  EXPECT_EQ(sideOf(s, -0.0125, -0.0125), Side::behindWall);      // beside the left corner
  EXPECT_EQ(sideOf(s, 0.4125, -0.0375), Side::behindWall);       // beside the right one
  EXPECT_EQ(sideOf(s, -0.03, 0.2), Side::behindWall);            // behind the left wall
  EXPECT_EQ(sideOf(s, 0.45, 0.2), Side::behindWall);             // behind the right wall
  EXPECT_EQ(sideOf(s, 0.2, -0.5 * dx), Side::behindWall);        // half a spacing below the bed
  EXPECT_EQ(sideOf(s, 0.2, -0.05 * dx), Side::material);         // within the tolerance
}

TEST(MaterialSideOfWalls, BelowTheBedBesideTheCornerParticleIsBehindThoughItsOwnNormalSaysWater) {
  const MaterialSideOfWalls s(openTank(), dx);
  for (const double depth : {0.5, 1.2, 3.0, 10.0}) {
    const auto v = s.classify(Vec3(0.1 * dx, -depth * dx, 0));
    EXPECT_EQ(v.wall, 0) << "the corner particle is the nearest";
    EXPECT_EQ(v.side, Side::behindWall) << depth << " dx below the bed";
    EXPECT_NEAR(v.depth, -depth * dx, 1e-12);
  }
}

TEST(MaterialSideOfWalls, BesideTheOpenTopsOnTheSolidSideIsPastAnOpenEnd) {
  const MaterialSideOfWalls s(openTank(), dx);
  EXPECT_EQ(sideOf(s, -0.0125, 0.55), Side::pastOpenEnd);
  EXPECT_EQ(sideOf(s, 0.43, 0.6), Side::pastOpenEnd);
  EXPECT_EQ(sideOf(s, 0.0125, 0.55), Side::material);
  EXPECT_EQ(sideOf(s, -0.03, 0.5 - 0.3 * dx), Side::behindWall);  // behind the end particle, not past it
}

// A block [0.1, 0.2] x [0, 0.1] on the bed y = 0 (-0.1 to 0.4): its wall particles face outwards.
TEST(MaterialSideOfWalls, BesideASolidBlocksCornersIsMaterialInsideItIsBehind) {
  std::vector<MaterialSideOfWalls::WallPoint> w;
  for (int i = -10; i <= 40; ++i) {
    if (i < 10 || i > 20) w.push_back({Vec3(i * dx, 0, 0), Vec3(0, 1, 0), 0});
  }
  for (int j = 0; j <= 10; ++j) w.push_back({Vec3(0.1, j * dx, 0), Vec3(-1, 0, 0), 1});
  for (int i = 11; i <= 20; ++i) w.push_back({Vec3(i * dx, 0.1, 0), Vec3(0, 1, 0), 1});
  for (int j = 0; j < 10; ++j) w.push_back({Vec3(0.2, j * dx, 0), Vec3(1, 0, 0), 1});
  const MaterialSideOfWalls s(std::move(w), dx);
  EXPECT_EQ(sideOf(s, 0.1 - 0.5 * dx, 0.1 + 0.5 * dx), Side::material);  // beside the top left corner
  EXPECT_EQ(sideOf(s, 0.2 + 0.5 * dx, 0.1 + 0.5 * dx), Side::material);
  EXPECT_EQ(sideOf(s, 0.2 + 0.1 * dx, 0.1 - 3 * dx), Side::material);    // beside the right face
  EXPECT_EQ(sideOf(s, 0.1 + 0.3 * dx, 0.1 - 1.2 * dx), Side::behindWall);  // in the block, by its corner
  EXPECT_EQ(sideOf(s, 0.15, 0.05), Side::behindWall);
  EXPECT_EQ(sideOf(s, 0.05, 0.5 * dx), Side::material);
}

TEST(MaterialSideOfWalls, AboveABlockBesideASideWallIsMaterial) {
  std::vector<MaterialSideOfWalls::WallPoint> w;
  for (int k = 0; k < 10; ++k) {
    const double z = (k + 0.5) * dx;
    for (int i = -10; i <= 40; ++i) {
      if (i < 10 || i > 20) w.push_back({Vec3(i * dx, 0, z), Vec3(0, 1, 0), 0});
    }
    for (int j = 0; j <= 10; ++j) w.push_back({Vec3(0.1, j * dx, z), Vec3(-1, 0, 0), 1});
    for (int i = 11; i <= 20; ++i) w.push_back({Vec3(i * dx, 0.1, z), Vec3(0, 1, 0), 1});
    for (int j = 0; j < 10; ++j) w.push_back({Vec3(0.2, j * dx, z), Vec3(1, 0, 0), 1});
  }
  for (int i = -10; i < 40; ++i) {  // the side wall: sites above the bed, outside the block
    for (int j = 0; j < 30; ++j) {
      const double x = (i + 0.5) * dx, y = (j + 0.5) * dx;
      if (x > 0.1 && x < 0.2 && y < 0.1) continue;
      w.push_back({Vec3(x, y, 0), Vec3(0, 0, 1), 2});
    }
  }
  const MaterialSideOfWalls s(std::move(w), dx);
  const auto at = [&](double x, double y, double z) { return s.classify(Vec3(x, y, z)).side; };
  for (const double x : {0.1 + 0.5 * dx, 0.1 + 1.5 * dx, 0.15, 0.2 - 0.5 * dx}) {
    EXPECT_EQ(at(x, 0.1 + dx, 0.5 * dx), Side::material) << "above the block by the side wall, x = " << x;
    EXPECT_EQ(at(x, 0.05, 0.5 * dx), Side::behindWall) << "in the block by the side wall, x = " << x;
  }
  EXPECT_EQ(at(0.1 - 0.5 * dx, 0.05, 0.5 * dx), Side::material);  // beside its faces
  EXPECT_EQ(at(0.2 + 0.5 * dx, 0.1 + 0.5 * dx, 0.5 * dx), Side::material);
  EXPECT_EQ(at(0.15, 0.1 + dx, -0.5 * dx), Side::behindWall);   // behind the side wall
  EXPECT_EQ(at(0.05, 0.05, -0.5 * dx), Side::behindWall);
}

TEST(MaterialSideOfWalls, OfCloudTakesTheWallParticlesNotTheDummies) {
  isph::ParticleCloud c;
  c.properties.spacing = dx;
  for (int i = 0; i <= 40; ++i) {
    c.push_back(Vec3(i * dx, 0, 0), i, Vec3::Zero(), 0, -1, isph::ParticleKind::wall, 0, Vec3(0, 1, 0), 0);
    c.push_back(Vec3(i * dx, -dx, 0), 100 + i, Vec3::Zero(), 0, -1, isph::ParticleKind::dummy, 0, Vec3(0, 1, 0), 0);
  }
  c.push_back(Vec3(0.2, 0.05, 0), 200, Vec3::Zero(), 0, 0, isph::ParticleKind::material, -1, Vec3::Zero(), 0);
  const auto s = MaterialSideOfWalls::ofCloud(c);
  EXPECT_EQ(s.walls().size(), 41u);
  EXPECT_EQ(sideOf(s, 0.2, -0.5 * dx), Side::behindWall);  // in front of a dummy, behind the wall
  EXPECT_TRUE(MaterialSideOfWalls({}, dx).empty());
  EXPECT_EQ(MaterialSideOfWalls({}, dx).classify(Vec3::Zero()).side, Side::material);
}

}  // namespace
