// The wall safeguard (WallPenetrationGuard.hpp) on a flat wall y = 0 (a row of wall particles
// dx apart, normal +y), 2D, Wendland C2, h = 1.3 dx, with distance 0.5 dx: a material particle
// beyond half a spacing from the wall surface is left alone; one closer is put back at half a
// spacing and loses the velocity it had into the wall, keeping the rest; one behind the wall
// surface is also a crossing, counted and described; a scene without walls has no guard.
// At the concave corner of a floor and a wall x = 0 (the corner's particle the wall's), a
// particle beside the corner, as near to the corner's particle as to the floor's first, is held
// above the floor too; above a convex corner (a block's top and its face) nothing more is held.
#include "isph/walls/WallPenetrationGuard.hpp"

#include <gtest/gtest.h>

#include "sph/kernels/Kernel.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01;

struct WallScene {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps;

  // Material particles at `heights` above the wall at x = 5.2 dx, 10.4 dx, ... (each over the
  // wall row, off its particles' centres), with velocity `u`.
  WallScene(const std::vector<double>& heights, const Vec3& u) {
    label id = 0;
    for (std::size_t i = 0; i < heights.size(); ++i) {
      ps.cloud.push_back(Vec3((5.2 + 8 * static_cast<double>(i)) * dx, heights[i], 0), id++, u, 0, 0,
                         ParticleKind::material, -1, Vec3::Zero(), 0.1);
    }
    for (int i = 0; i < 10 * static_cast<int>(heights.size()); ++i) {
      ps.cloud.push_back(Vec3((i + 0.5) * dx, 0, 0), id++, Vec3::Zero(), 0, -1, ParticleKind::wall, 0, Vec3(0, 1, 0),
                         0.1);
    }
    ps.dx = dx;
    ps.nMaterial = heights.size();
    ps.nWall = ps.cloud.size() - ps.nMaterial;
    ps.neighbours.build(ps.cloud.positions, *kernel);
  }
};

TEST(WallPenetrationGuard, LeavesAParticleBeyondHalfASpacingAlone) {
  WallScene s({0.6 * dx}, Vec3(0.3, -0.2, 0));
  const WallGuardResult r = guardWallPenetration(s.ps, 0.5);
  EXPECT_EQ(r.moved, 0u);
  EXPECT_EQ(r.crossed, 0u);
  EXPECT_EQ(s.ps.cloud.positions[0].y(), 0.6 * dx);
  EXPECT_EQ(s.ps.cloud.U[0], Vec3(0.3, -0.2, 0));
}

TEST(WallPenetrationGuard, PutsACloseParticleBackAndTakesItsVelocityIntoTheWall) {
  WallScene s({0.2 * dx}, Vec3(0.3, -0.2, 0));
  const WallGuardResult r = guardWallPenetration(s.ps, 0.5);
  EXPECT_EQ(r.moved, 1u);
  EXPECT_EQ(r.crossed, 0u) << "in front of the wall: no crossing";
  EXPECT_TRUE(r.firstCrossing.empty());
  EXPECT_NEAR(s.ps.cloud.positions[0].y(), 0.5 * dx, 1e-15);
  EXPECT_EQ(s.ps.cloud.positions[0].x(), 5.2 * dx) << "moved along the wall normal only";
  EXPECT_NEAR(s.ps.cloud.U[0].y(), 0.0, 1e-15) << "the velocity into the wall is lost";
  EXPECT_EQ(s.ps.cloud.U[0].x(), 0.3) << "the tangential velocity is kept";
}

TEST(WallPenetrationGuard, KeepsAVelocityAwayFromTheWall) {
  WallScene s({0.2 * dx}, Vec3(0.3, 0.2, 0));
  guardWallPenetration(s.ps, 0.5);
  EXPECT_EQ(s.ps.cloud.U[0], Vec3(0.3, 0.2, 0));
}

TEST(WallPenetrationGuard, CountsAndDescribesACrossing) {
  WallScene s({0.8 * dx, -0.1 * dx}, Vec3(0, -1, 0));
  const WallGuardResult r = guardWallPenetration(s.ps, 0.5);
  EXPECT_EQ(r.moved, 1u);
  EXPECT_EQ(r.crossed, 1u);
  EXPECT_NE(r.firstCrossing.find("origId 1)"), std::string::npos) << r.firstCrossing;
  EXPECT_NEAR(s.ps.cloud.positions[1].y(), 0.5 * dx, 1e-15) << "put back in front of the wall";
  EXPECT_EQ(s.ps.cloud.positions[0].y(), 0.8 * dx);
}

TEST(WallPenetrationGuard, NoWallsNoGuard) {
  WallScene s({0.2 * dx}, Vec3(0, -1, 0));
  s.ps.nWall = 0;
  s.ps.nMaterial = s.ps.cloud.size();  // the wall row as material: no wall at all
  const WallGuardResult r = guardWallPenetration(s.ps, 0.5);
  EXPECT_EQ(r.moved, 0u);
  EXPECT_EQ(s.ps.cloud.positions[0].y(), 0.2 * dx);
}

// The corner of a floor y = 0 (particles at x = dx, 2 dx, ..., normal +y) and a wall x = 0
// (particles at y = 0, dx, 2 dx, ..., normal +x: the corner's particle is the wall's), or with
// `convex`, a block's corner: its top y = 0 (x = 0, -dx, ..., normal +y, the corner's particle
// the top's) and its face x = 0 (y = -dx, -2 dx, ..., normal +x); one material particle at `at`.
struct CornerScene {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps;

  CornerScene(const Vec3& at, const Vec3& u, bool convex = false) {
    label id = 0;
    ps.cloud.push_back(at, id++, u, 0, 0, ParticleKind::material, -1, Vec3::Zero(), 0.1);
    for (int i = 0; i < 8; ++i) {
      const Vec3 wall = convex ? Vec3(0, -(i + 1) * dx, 0) : Vec3(0, i * dx, 0);
      const Vec3 floor = convex ? Vec3(-i * dx, 0, 0) : Vec3((i + 1) * dx, 0, 0);
      ps.cloud.push_back(wall, id++, Vec3::Zero(), 0, -1, ParticleKind::wall, 0, Vec3(1, 0, 0), 0.1);
      ps.cloud.push_back(floor, id++, Vec3::Zero(), 0, -1, ParticleKind::wall, 1, Vec3(0, 1, 0), 0.1);
    }
    ps.dx = dx;
    ps.nMaterial = 1;
    ps.nWall = ps.cloud.size() - 1;
    ps.neighbours.build(ps.cloud.positions, *kernel);
  }
};

TEST(WallPenetrationGuard, HoldsAParticleBesideAConcaveCornerAboveTheFloor) {
  // Half a spacing from the wall (where the guard holds it), sinking below the floor: as near to
  // the corner's particle (0, 0) as to the floor's (dx, 0). Before the corner's partner was
  // guarded it was left there (the wall's normal +x saw it half a spacing away) and sank on.
  CornerScene s(Vec3(0.5 * dx, -0.1 * dx, 0), Vec3(0, -0.1, 0));
  const WallGuardResult r = guardWallPenetration(s.ps, 0.5);
  EXPECT_EQ(r.moved, 1u);
  EXPECT_EQ(r.crossed, 1u) << "it was behind the floor";
  EXPECT_NEAR(s.ps.cloud.positions[0].y(), 0.5 * dx, 1e-15) << "put back half a spacing above the floor";
  EXPECT_NEAR(s.ps.cloud.positions[0].x(), 0.5 * dx, 1e-15) << "and still half a spacing from the wall";
  EXPECT_NEAR(s.ps.cloud.U[0].y(), 0.0, 1e-15) << "its velocity into the floor is lost";
}

TEST(WallPenetrationGuard, HoldsAParticleInAConcaveCornerFromBothWalls) {
  CornerScene s(Vec3(0.3 * dx, 0.2 * dx, 0), Vec3(-0.1, -0.1, 0));
  const WallGuardResult r = guardWallPenetration(s.ps, 0.5);
  EXPECT_EQ(r.moved, 1u);
  EXPECT_EQ(r.crossed, 0u);
  EXPECT_NEAR(s.ps.cloud.positions[0].x(), 0.5 * dx, 1e-15);
  EXPECT_NEAR(s.ps.cloud.positions[0].y(), 0.5 * dx, 1e-15);
  EXPECT_NEAR(s.ps.cloud.U[0].norm(), 0.0, 1e-15);
}

TEST(WallPenetrationGuard, AddsNothingAboveAConvexCorner) {
  // Above the block's top, beyond its face: the top's plane alone; the face (its particles
  // behind the top's plane) is no partner, and the particle stays where it is.
  CornerScene s(Vec3(0.3 * dx, 0.6 * dx, 0), Vec3(-0.1, -0.1, 0), true);
  const WallGuardResult r = guardWallPenetration(s.ps, 0.5);
  EXPECT_EQ(r.moved, 0u);
  EXPECT_EQ(s.ps.cloud.positions[0], Vec3(0.3 * dx, 0.6 * dx, 0));
  EXPECT_EQ(s.ps.cloud.U[0], Vec3(-0.1, -0.1, 0));
}

}  // namespace
