// The wall safeguard (WallPenetrationGuard.hpp) on a flat wall y = 0 (a row of wall particles
// dx apart, normal +y), 2D, Wendland C2, h = 1.3 dx, with distance 0.5 dx: a material particle
// beyond half a spacing from the wall surface is left alone; one closer is put back at half a
// spacing and loses the velocity it had into the wall, keeping the rest; one behind the wall
// surface is also a crossing, counted and described; a scene without walls has no guard.
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

}  // namespace
