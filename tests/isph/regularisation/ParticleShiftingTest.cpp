// Fickian shifting (ParticleShifting) on a block of material particles, 2D, Wendland C2 with
// h = 1.3 dx, in simple shear u = (γ̇ y + U0, 0) with γ̇ = 100 /s (relative speeds of order
// 1 m/s across a support, as the block moving at 1 m/s had when shifting took |u|), dt = 1e-3 s,
// no walls. The top row is the free
// surface (flagged by hand, as the FreeSurfaceDetector would). Inside, the Lind et al. (2012)
// shift evens the distribution; the free surface is not moved; next to it nothing moves by
// default, and with `nearSurface pairs` only a pair closer than dx, pushed apart along its line.
#include <gtest/gtest.h>

#include <cmath>

#include "isph/regularisation/ParticleShifting.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01, dt = 1e-3;
constexpr int nx = 12, ny = 8;  // rows 0 .. 7, row 7 the free surface

struct Block {
  ParticleSystem ps;
  std::vector<char> surface;
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);

  // The lattice, with particle `moved` (if any) displaced by `offset`.
  explicit Block(int moved = -1, Vec3 offset = Vec3::Zero(), double shearRate = 100.0, double U0 = 0.0) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        ps.cloud.positions.emplace_back((i + 0.5) * dx, (j + 0.5) * dx, 0.0);
        surface.push_back(j == ny - 1 ? 1 : 0);
      }
    }
    const std::size_t n = ps.cloud.positions.size();
    if (moved >= 0) ps.cloud.positions[static_cast<std::size_t>(moved)] += offset;
    for (const Vec3& x : ps.cloud.positions) ps.cloud.U.emplace_back(shearRate * x.y() + U0, 0.0, 0.0);
    ps.cloud.p.assign(n, 0.0);
    ps.cloud.normal.assign(n, Vec3::Zero());
    ps.dimension = 2;
    ps.dx = dx;
    ps.nMaterial = n;
    ps.volume.assign(n, dx * dx);
    ps.neighbours.build(ps.cloud.positions, *kernel);
  }

  Vec3 shiftOf(std::size_t a, bool pairsNearSurface = false, bool deformationSpeed = true) {
    const Vec3 before = ps.cloud.positions[a];
    ShiftingSettings settings;
    settings.pairsNearSurface = pairsNearSurface;
    settings.deformationSpeed = deformationSpeed;
    shiftParticles(ps, *kernel, surface, settings, IsphSchemes{}.correctionMinDeterminant, true, dt);
    return ps.cloud.positions[a] - before;
  }
};

std::size_t at(int i, int j) { return static_cast<std::size_t>(j * nx + i); }

// Particle (6, 6), next to the surface row, moved 0.5 dx down onto (6, 5)'s upper half.
Block pairBelowTheSurface() { return Block(static_cast<int>(at(6, 6)), Vec3(0.0, -0.5 * dx, 0.0)); }

TEST(ParticleShifting, NextToTheSurfaceNothingMovesByDefault) {
  Block b = pairBelowTheSurface();
  EXPECT_LT(b.shiftOf(at(6, 5)).norm(), 1e-12 * dx);
}

TEST(ParticleShifting, PairsNearSurfaceSeparatesAPairAlongItsLine) {
  Block b = pairBelowTheSurface();
  const Vec3 s = b.shiftOf(at(6, 5), true);
  EXPECT_LT(s.y(), -0.01 * dx) << "the lower particle of the pair moves away from the upper one";
  EXPECT_LT(std::abs(s.x()), 0.05 * std::abs(s.y())) << "along the line of centres";
  EXPECT_LE(s.norm(), ShiftingSettings().maxShift * dx * (1 + 1e-12)) << "capped at maxShift dx";
}

TEST(ParticleShifting, PairsNearSurfaceLeavesTheLatticeWhereItIs) {
  Block b;
  EXPECT_LT(b.shiftOf(at(6, 6), true).norm(), 1e-12 * dx) << "no neighbour is closer than dx";
}

TEST(ParticleShifting, DoesNotMoveTheFreeSurface) {
  Block b(static_cast<int>(at(6, 6)), Vec3(0.0, 0.5 * dx, 0.0));  // a pair in the surface row
  EXPECT_EQ(b.shiftOf(at(6, 7)).norm(), 0.0);
}

TEST(ParticleShifting, TheDeformationSpeedIsTheShearRateTimesH) {
  // A linear shear u = (γ̇ y, 0): |γ̇| = γ̇ exactly (the renormalised gradient is exact for a
  // linear field), so h |γ̇| = 1.3 dx × 100 /s, in any frame; a rigid rotation deforms nothing.
  const double h = 1.3 * dx, expected = h * 100.0;
  Block b;
  EXPECT_NEAR(deformationSpeed(b.ps, *b.kernel, at(6, 3), 0.25), expected, 1e-12 * expected);
  Block moving(-1, Vec3::Zero(), 100.0, 7.0);  // the same shear seen from a frame moving at -7 m/s
  EXPECT_NEAR(deformationSpeed(moving.ps, *moving.kernel, at(6, 3), 0.25), expected, 1e-12 * expected);
  Block turning;
  for (std::size_t a = 0; a < turning.ps.nMaterial; ++a) {
    const Vec3& x = turning.ps.cloud.positions[a];
    turning.ps.cloud.U[a] = 50.0 * Vec3(-(x.y() - 0.04), x.x() - 0.06, 0.0);  // ω = 50 rad/s about (0.06, 0.04)
  }
  EXPECT_NEAR(deformationSpeed(turning.ps, *turning.kernel, at(6, 3), 0.25), 0.0, 1e-12 * expected);
}

TEST(ParticleShifting, ABlockMovingAsAWholeIsNotShiftedByTheSpeedOfDeformation) {
  // The interior particle displaced as below, in a block translating at 1 m/s: no deformation,
  // no shift; Lind's |u| (`speed velocity`) shifts it (slidingBlock's block spread as it slid).
  Block b(static_cast<int>(at(6, 2)), Vec3(0.2 * dx, 0.0, 0.0), 0.0, 1.0);
  EXPECT_EQ(b.shiftOf(at(6, 2)).norm(), 0.0);
  Block lind(static_cast<int>(at(6, 2)), Vec3(0.2 * dx, 0.0, 0.0), 0.0, 1.0);
  EXPECT_LT(lind.shiftOf(at(6, 2), false, false).x(), -0.01 * dx);
}

TEST(ParticleShifting, EvensTheInteriorWithTheFullShift) {
  // Row 2, out of reach of the surface row (the support is 2.6 dx): particle (6, 2) moved
  // 0.2 dx to the right is pushed back to the left, by a visible part of a spacing.
  Block b(static_cast<int>(at(6, 2)), Vec3(0.2 * dx, 0.0, 0.0));
  EXPECT_LT(b.shiftOf(at(6, 2)).x(), -0.01 * dx);
}

}  // namespace
