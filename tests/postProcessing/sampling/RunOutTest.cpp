#include "postProcessing/sampling/RunOut.hpp"

#include <gtest/gtest.h>

namespace {

using namespace isph;

// A 10 × 3 block of material on a 0.01 m lattice from x = 0.005 to 0.095, plus what a test adds.
ParticleCloud block() {
  ParticleCloud c;
  c.properties.spacing = 0.01;
  label id = 0;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 3; ++j)
      c.push_back(Vec3(0.005 + 0.01 * i, 0.005 + 0.01 * j, 0), id++, Vec3::Zero(), 0, 0, ParticleKind::material, -1,
                  Vec3::Zero(), 0.1);
  return c;
}

TEST(RunOut, IsTheFarthestMaterialParticlePlusHalfASpacing) {
  const auto front = runOut(block(), RunOutSpec{});
  ASSERT_TRUE(front);
  EXPECT_NEAR(*front, 0.1, 1e-12);
}

TEST(RunOut, IgnoresWallsSprayAboveTheBandAndLoneParticles) {
  ParticleCloud c = block();
  c.push_back(Vec3(0.3, 0.005, 0), 100, Vec3::Zero(), 0, -1, ParticleKind::wall, 0, Vec3::UnitY(), 0);
  c.push_back(Vec3(0.2, 0.2, 0), 101, Vec3::Zero(), 0, 0, ParticleKind::material, -1, Vec3::Zero(), 0.1);   // spray
  c.push_back(Vec3(0.15, 0.005, 0), 102, Vec3::Zero(), 0, 0, ParticleKind::material, -1, Vec3::Zero(), 0.1);  // lone
  RunOutSpec s;
  s.maxHeight = 0.05;
  EXPECT_NEAR(*runOut(c, s), 0.155, 1e-12) << "the lone particle counts when minNeighbours is 0";
  s.minNeighbours = 2;
  EXPECT_NEAR(*runOut(c, s), 0.1, 1e-12);
}

TEST(RunOut, MeasuresAlongAnyDirectionFromTheOrigin) {
  RunOutSpec s;
  s.origin = Vec3(0.1, 0, 0);
  s.direction = Vec3(-2, 0, 0);  // back towards x = 0, not normalised
  EXPECT_NEAR(*runOut(block(), s), 0.1, 1e-12);
}

// In 3D the band is a height above the bed line, whatever z: the block repeated over a flume
// 0.2 m wide has its front at every z (measured from the line through the origin, the front
// at z = 0.195 lay 0.195 m from it, and a band of 0.05 m left only the rows near z = 0).
TEST(RunOut, InThreeDimensionsTheBandIsAHeightAtEveryZ) {
  ParticleCloud c;
  c.properties.spacing = 0.01;
  c.properties.dimension = 3;
  label id = 0;
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < (k < 19 ? 10 : 12); ++i)  // the last row across runs 2 spacings ahead
        c.push_back(Vec3(0.005 + 0.01 * i, 0.005 + 0.01 * j, 0.005 + 0.01 * k), id++, Vec3::Zero(), 0, 0,
                    ParticleKind::material, -1, Vec3::Zero(), 0.1);
  RunOutSpec s;
  s.maxHeight = 0.05;
  s.minNeighbours = 2;
  EXPECT_NEAR(*runOut(c, s), 0.12, 1e-12);
  EXPECT_EQ(heightAxis(Vec3(2, 0, 0)), Vec3(0, 1, 0));
  EXPECT_EQ(heightAxis(Vec3(0, 0, 1)), Vec3(0, 1, 0));
  s.origin = Vec3(0, 0.06, 0);  // the band 0.01 <= y <= 0.11 holds the rows above y = 0.01
  EXPECT_NEAR(*runOut(c, s), 0.12, 1e-12);
  s.origin = Vec3(0, 0.2, 0);
  EXPECT_FALSE(runOut(c, s));
}

TEST(RunOut, NothingWhenNoMaterialIsInTheBand) {
  RunOutSpec s;
  s.origin = Vec3(0, 1, 0);
  s.maxHeight = 0.1;
  EXPECT_FALSE(runOut(block(), s));
}

}  // namespace
