// smoothedPressure (LaggedPressure.hpp), the Shepard passes over the pressure that the
// incremental projection's gradient form lags: on a lattice block (Wendland C2, h = 1.3 dx)
// a linear pressure is kept where the support is full, the free surface stays at p = 0, and
// a single-particle spike is spread over its neighbours.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "LatticeBlockForTest.hpp"
#include "isph/LaggedPressure.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01;
constexpr int n = 12;

ParticleSystem block(const Kernel& kernel) { return test::latticeBlock(kernel, n, dx); }

// Whether lattice particle (i, j) has a full support: at least three rows from every edge.
bool interior(int i, int j) { return i >= 3 && j >= 3 && i < n - 3 && j < n - 3; }

TEST(LaggedPressure, ShepardPassesKeepALinearPressureInsideAndTheSurfaceAtZero) {
  const auto kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps = block(*kernel);
  std::vector<char> surface(ps.nMaterial, 0);
  ps.cloud.p.resize(ps.nMaterial);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto a = static_cast<std::size_t>(j * n + i);
      ps.cloud.p[a] = 1000.0 * (n - 0.5 - j) * dx + 200.0 * i * dx;  // lithostatic plus a tilt
      surface[a] = j == n - 1;
      if (surface[a]) ps.cloud.p[a] = 0.0;
    }
  }
  const std::vector<double> one = smoothedPressure(ps, *kernel, surface, 1);
  const std::vector<double> none = smoothedPressure(ps, *kernel, surface, 0);
  ASSERT_EQ(one.size(), ps.nMaterial);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto a = static_cast<std::size_t>(j * n + i);
      EXPECT_EQ(none[a], ps.cloud.p[a]) << "no pass: pⁿ as it is";
      if (surface[a]) {
        EXPECT_EQ(one[a], 0.0) << "the free surface holds p = 0";
      }
      if (interior(i, j) && j < n - 4) {
        EXPECT_NEAR(one[a], ps.cloud.p[a], 1e-9 * 1000.0) << "a linear field inside, particle (" << i << ", " << j << ")";
      }
    }
  }
}

TEST(LaggedPressure, ASpikeIsSpreadOverItsNeighbours) {
  const auto kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps = block(*kernel);
  const std::vector<char> surface(ps.nMaterial, 0);
  ps.cloud.p.assign(ps.nMaterial, 100.0);
  const std::size_t spike = 6 * n + 6;
  ps.cloud.p[spike] = 10100.0;
  const std::vector<double> one = smoothedPressure(ps, *kernel, surface, 1);
  // The spike keeps its own Shepard weight V W(0) / Σ V W of the excess: a third with
  // Wendland C2 at h = 1.3 dx in 2D.
  const double W0 = kernel->W(0.0);
  double weight = dx * dx * W0;
  for (long k = ps.neighbours.start[spike]; k < ps.neighbours.start[spike + 1]; ++k) {
    weight += dx * dx * ps.neighbours.W[static_cast<std::size_t>(k)];
  }
  EXPECT_NEAR(one[spike], 100.0 + 10000.0 * dx * dx * W0 / weight, 1e-9);
  EXPECT_LT(one[spike], 100.0 + 0.35 * 10000.0);
  // Its neighbours take the rest, and the total excess over the block is about conserved.
  double excess = 0;
  for (double v : one) excess += v - 100.0;
  EXPECT_NEAR(excess, 10000.0, 0.05 * 10000.0);
}

}  // namespace
