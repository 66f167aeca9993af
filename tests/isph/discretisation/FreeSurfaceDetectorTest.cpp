// FreeSurfaceDetector in 2D: the sector of a direction (supportSector) against its definition
// by atan2, and the detector on a lattice block of material (Wendland C2, h = 1.3 dx, no
// walls): the outer ring of particles is the surface, the interior is not, and a particle
// whose support has one empty 45° sector is flagged although its ∇·r is that of the
// interior.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "LatticeBlockForTest.hpp"
#include "isph/discretisation/FreeSurfaceDetector.hpp"

namespace {

using namespace isph;

// The definition: θ + π + π/8 in [kπ/4, (k+1)π/4), θ = atan2(y, x).
int sectorByAtan2(double x, double y) {
  const double angle = std::atan2(y, x) + M_PI + M_PI / 8;
  return static_cast<int>(static_cast<unsigned>(angle / (M_PI / 4)) & 7u);
}

TEST(FreeSurfaceDetector, SupportSectorIsTheSectorOfTheAngle) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), radius(1e-3, 2.0);
  int checked = 0;
  for (int k = 0; k < 100000; ++k) {
    const double t = angle(rng), r = radius(rng);
    // away from the edges (θ + π/8 a multiple of π/4), where either sector is allowed
    const double fromEdge = std::remainder(t + M_PI / 8, M_PI / 4);
    if (std::abs(fromEdge) < 1e-9) continue;
    ASSERT_EQ(supportSector(r * std::cos(t), r * std::sin(t)), sectorByAtan2(r * std::cos(t), r * std::sin(t)))
        << "theta " << t;
    ++checked;
  }
  EXPECT_GT(checked, 99000);
}

TEST(FreeSurfaceDetector, EachLatticeDirectionHasASectorOfItsOwn) {
  unsigned occupied = 0;
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) {
      if (i != 0 || j != 0) occupied |= 1u << static_cast<unsigned>(supportSector(i, j));
    }
  }
  EXPECT_EQ(occupied, 0xffu) << "the eight lattice directions fill the eight sectors";
  EXPECT_EQ(supportSector(-1, 0), 0);  // θ = π: the first sector, by the definition's wrap
  EXPECT_EQ(supportSector(1, 0), 4);
  EXPECT_EQ(supportSector(0, 1), 6);
  EXPECT_EQ(supportSector(0, -1), 2);
}

constexpr double dx = 0.01;
constexpr int n = 10;

// The n × n block without the particles of `removed` (lattice indices j n + i).
ParticleSystem block(const Kernel& kernel, const std::vector<int>& removed = {}) {
  return test::latticeBlock(kernel, n, dx, removed);
}

FreeSurfaceDetector detector(const Kernel& kernel) {
  return FreeSurfaceDetector(1.5, 0.5, 0.5, fullLatticeNeighbourCount(kernel, dx, "square", 2), kernel.h());
}

TEST(FreeSurfaceDetector, TheOuterRingOfALatticeBlockIsTheSurface) {
  const auto kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  const ParticleSystem ps = block(*kernel);
  FreeSurfaceDetector d = detector(*kernel);
  d.detect(ps);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const bool ring = i == 0 || j == 0 || i == n - 1 || j == n - 1;
      EXPECT_EQ(d.flags()[static_cast<std::size_t>(j * n + i)] != 0, ring) << "particle (" << i << ", " << j << ")";
    }
  }
  EXPECT_EQ(d.nSurfaceMaterial(), static_cast<std::size_t>(4 * n - 4));
}

// A vacancy inside: each of its neighbours still finds a particle in every sector (the next
// one along that line lies within the support, 2.6 dx), and keeps ∇·r above 1.5: no surface.
TEST(FreeSurfaceDetector, ASingleVacancyInsideIsNotASurface) {
  const auto kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  const ParticleSystem ps = block(*kernel, {5 * n + 5});
  FreeSurfaceDetector d = detector(*kernel);
  d.detect(ps);
  EXPECT_EQ(d.nSurfaceMaterial(), static_cast<std::size_t>(4 * n - 4));
}

// Particle (4, 5) with the two particles to its right, (5, 5) and (6, 5), taken away: the
// sector along +x (±22.5°) of its support is empty, while ∇·r, missing only those two, stays
// above the threshold 1.5. The sector scan alone flags it.
TEST(FreeSurfaceDetector, AnEmptySectorMakesASurfaceWhereDivergenceDoesNot) {
  const auto kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  const ParticleSystem ps = block(*kernel, {5 * n + 5, 5 * n + 6});
  FreeSurfaceDetector d = detector(*kernel);
  d.detect(ps);
  const std::size_t a = 5 * n + 4;  // (4, 5): no particle removed before it
  ASSERT_NEAR(ps.cloud.positions[a].x(), 4.5 * dx, 1e-12);
  ASSERT_NEAR(ps.cloud.positions[a].y(), 5.5 * dx, 1e-12);
  EXPECT_GT(d.divergence()[a], 1.5) << "the divergence test alone would call it interior";
  EXPECT_TRUE(d.flags()[a]) << "its empty sector makes it a surface particle";
}

}  // namespace
