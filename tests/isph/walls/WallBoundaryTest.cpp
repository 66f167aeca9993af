// The walls' state at the step start (WallBoundary::prepare) on a 10 × 10 lattice block of
// material, 2D, Wendland C2, h = 1.3 dx, under a linear pressure p = 1000 Pa + 500 Pa/m · y:
// each particle's pull limit is its pressure (no pull below zero), 0 on the free surface; the
// pressure gradient along a friction wall is the material's own for a material that slides
// (exact for a linear field with the material-only renormalisation where the support allows
// it), ρ g for one that sticks.
#include "isph/walls/WallBoundary.hpp"

#include <gtest/gtest.h>

#include "LatticeBlockForTest.hpp"
#include "MaterialTableForTest.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01, rho = 2000;
constexpr int n = 10;
const Vec3 g(0, -9.81, 0);

struct Block {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps = test::latticeBlock(*kernel, n, dx);
  std::unique_ptr<MaterialTable> materials;
  std::vector<char> surface = std::vector<char>(ps.nMaterial, 0);

  explicit Block(const std::string& model) {
    materials = test::materialTable("WallBoundaryTest", "soil { " + model + " }", {"soil"});
    ps.cloud.material.assign(ps.nMaterial, 0);
    ps.rho.assign(ps.nMaterial, rho);
    ps.cloud.p.resize(ps.nMaterial);
    for (std::size_t a = 0; a < ps.nMaterial; ++a) ps.cloud.p[a] = 1000 + 500 * ps.cloud.positions[a].y();
    ps.cloud.p[3] = -20;  // a particle under tension
    for (int i = 0; i < n; ++i) surface[static_cast<std::size_t>((n - 1) * n + i)] = 1;  // the top row
  }
};

TEST(WallBoundary, ThePullLimitIsThePressureAndZeroOnTheFreeSurface) {
  Block b("model newtonian; rho 2000; nu 1e-6;");
  WallBoundary(b.ps, *b.materials, g, 0.25, false).prepare(b.surface);
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    const double expected = b.surface[a] ? 0.0 : std::max(b.ps.cloud.p[a], 0.0);
    EXPECT_EQ(b.ps.wallPullLimit[a], expected) << "particle " << a;
  }
  EXPECT_EQ(b.ps.wallPullLimit[3], 0.0) << "no pull below zero";
}

TEST(WallBoundary, AStickingMaterialTakesTheHydrostaticGradientAlongTheWalls) {
  Block b("model newtonian; rho 2000; nu 1e-6;");
  WallBoundary(b.ps, *b.materials, g, 0.25, false).prepare(b.surface);
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) EXPECT_EQ(b.ps.wallTangentialGradient[a], Vec3(rho * g));
}

TEST(WallBoundary, ASlidingMaterialTakesItsOwnPressureGradientAlongTheWalls) {
  Block b("model rigidPlastic; rho 2000; phi 30;");
  b.ps.cloud.p[3] = 1000 + 500 * b.ps.cloud.positions[3].y();  // the linear field everywhere
  WallBoundary(b.ps, *b.materials, g, 0.25, true).prepare(b.surface);
  // Exact wherever the material-only moment can be inverted (measured 3.4e-13 Pa/m); in the
  // four corners, a quarter support, its determinant is below correctionMinDeterminant (0.25)
  // and the plain sum is taken, off by 63 % (313 Pa/m).
  double worst = 0;
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    const bool corner = a == 0 || a == n - 1 || a == (n - 1) * n || a == n * n - 1;
    const double error = (b.ps.wallTangentialGradient[a] - Vec3(0, 500, 0)).norm();
    if (corner) {
      EXPECT_GT(error, 100.0) << "corner " << a << ": the uncorrected sum";
    } else {
      worst = std::max(worst, error);
    }
  }
  EXPECT_LT(worst, 1e-9) << "the renormalised gradient of a linear field is exact";
}

}  // namespace
