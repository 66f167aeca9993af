// The minimum distance between material particles (ParticleCollision.hpp), 2D, Wendland C2,
// h = 1.3 dx, distance 0.5 dx: a pair closer than half a spacing is parted to it, each by its
// mass share of the overlap along the line of centres; their approaching normal velocity is
// lost and their momentum kept; a separating pair keeps its velocities; pairs further apart
// and a distance of 0 (off) leave everything alone.
#include "isph/regularisation/ParticleCollision.hpp"

#include <gtest/gtest.h>

#include "sph/kernels/Kernel.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01;

struct Pair {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps;

  // Particle 0 at the origin, particle 1 at `r` along the unit vector (0.6, 0.8).
  Pair(double r, const Vec3& u0, const Vec3& u1, double m0 = 0.1, double m1 = 0.1) {
    ps.cloud.push_back(Vec3::Zero(), 0, u0, 0, 0, ParticleKind::material, -1, Vec3::Zero(), m0);
    ps.cloud.push_back(r * Vec3(0.6, 0.8, 0), 1, u1, 0, 0, ParticleKind::material, -1, Vec3::Zero(), m1);
    ps.dx = dx;
    ps.nMaterial = 2;
    ps.neighbours.build(ps.cloud.positions, *kernel);
  }
  double distance() const { return (ps.cloud.positions[1] - ps.cloud.positions[0]).norm(); }
  Vec3 momentum() const { return ps.cloud.mass[0] * ps.cloud.U[0] + ps.cloud.mass[1] * ps.cloud.U[1]; }
};

const Vec3 e(0.6, 0.8, 0), t(-0.8, 0.6, 0);  // the line of centres and its tangent

TEST(ParticleCollision, PartsAClosePairToTheDistanceAndStopsItsApproach) {
  Pair p(0.2 * dx, Vec3(1.0 * e + 0.5 * t), Vec3(-1.0 * e));
  const Vec3 before = p.momentum();
  EXPECT_EQ(separateCloseParticles(p.ps, 0.5).moved, 2u);
  EXPECT_NEAR(p.distance(), 0.5 * dx, 1e-15);
  EXPECT_NEAR(p.ps.cloud.positions[0].dot(e), -0.15 * dx, 1e-15) << "half the overlap each (equal masses)";
  const double approach = (p.ps.cloud.U[1] - p.ps.cloud.U[0]).dot(e);
  EXPECT_NEAR(approach, 0.0, 1e-14) << "perfectly inelastic along the line of centres";
  EXPECT_NEAR(p.ps.cloud.U[0].dot(t), 0.5, 1e-14) << "the tangential velocity is kept";
  EXPECT_NEAR((p.momentum() - before).norm(), 0.0, 1e-15);
}

TEST(ParticleCollision, SharesTheCorrectionByMass) {
  Pair p(0.2 * dx, Vec3(1.0 * e), Vec3::Zero(), 0.3, 0.1);
  const Vec3 before = p.momentum();
  separateCloseParticles(p.ps, 0.5);
  // The heavier particle (3/4 of the mass) moves a quarter of the 0.3 dx overlap.
  EXPECT_NEAR(p.ps.cloud.positions[0].dot(e), -0.075 * dx, 1e-15);
  EXPECT_NEAR(p.ps.cloud.positions[1].dot(e), 0.2 * dx + 0.225 * dx, 1e-15);
  EXPECT_NEAR((p.ps.cloud.U[1] - p.ps.cloud.U[0]).dot(e), 0.0, 1e-14);
  EXPECT_NEAR((p.momentum() - before).norm(), 0.0, 1e-15);
}

TEST(ParticleCollision, ASeparatingPairKeepsItsVelocities) {
  Pair p(0.2 * dx, Vec3(-1.0 * e), Vec3(1.0 * e));
  separateCloseParticles(p.ps, 0.5);
  EXPECT_NEAR(p.distance(), 0.5 * dx, 1e-15);
  EXPECT_EQ(p.ps.cloud.U[0], Vec3(-1.0 * e));
  EXPECT_EQ(p.ps.cloud.U[1], Vec3(1.0 * e));
}

TEST(ParticleCollision, LeavesAPairBeyondTheDistanceAndIsOffAtZero) {
  Pair far(0.6 * dx, Vec3(1.0 * e), Vec3(-1.0 * e));
  EXPECT_EQ(separateCloseParticles(far.ps, 0.5).moved, 0u);
  EXPECT_NEAR(far.distance(), 0.6 * dx, 1e-15);
  Pair off(0.2 * dx, Vec3(1.0 * e), Vec3(-1.0 * e));
  EXPECT_EQ(separateCloseParticles(off.ps, 0.0).moved, 0u);
  EXPECT_NEAR(off.distance(), 0.2 * dx, 1e-15);
}

}  // namespace
