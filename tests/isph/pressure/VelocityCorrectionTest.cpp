// Eq. 11 (VelocityCorrection.hpp), 2D, Wendland C2 with h = 1.3 dx, on a 12 × 12 lattice block
// of material at a uniform 1000 Pa, u* = 0, one interior particle moved to half a spacing from
// its right-hand neighbour (a pair, as a thin granular stream forms them;
// doc/notes/granularSlope.md): the renormalised difference form L_a Σ V_b (p_b − p_a)∇W sees
// no gradient in a uniform pressure, so nothing moves, the pair included.
#include <gtest/gtest.h>

#include <cmath>

#include "LatticeBlockForTest.hpp"
#include "isph/discretisation/KernelGradientCorrection.hpp"
#include "isph/pressure/VelocityCorrection.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01, rho = 1000, p0 = 1000, dt = 1e-3;
constexpr int n = 12;
constexpr int moved = 5 * n + 5;  // lattice particle (5, 5), moved towards (6, 5)

struct PairedBlock {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps;
  KernelGradientCorrection L;

  PairedBlock() {
    ps = test::latticeBlock(*kernel, n, dx);
    ps.cloud.positions[moved].x() += 0.5 * dx;  // half a spacing from its partner
    ps.neighbours.build(ps.cloud.positions, *kernel);
    const std::size_t count = ps.nMaterial;
    ps.rho.assign(count, rho);
    ps.cloud.mass.assign(count, rho * dx * dx);
    ps.cloud.p.assign(count, p0);
    ps.cloud.U.assign(count, Vec3::Zero());
    ps.wallPullLimit.assign(count, p0);
    ps.wallTangentialGradient.assign(count, Vec3::Zero());
    L.update(ps, true, 0.25);
  }
};

TEST(VelocityCorrection, TheDifferenceFormLeavesAPairAtUniformPressureAlone) {
  PairedBlock b;
  const std::vector<Vec3> ustar(b.ps.nMaterial, Vec3::Zero());
  correctVelocity(b.ps, b.L, ustar, Vec3(0, -9.81, 0), dt);
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) EXPECT_LT(b.ps.cloud.U[a].norm(), 1e-12) << "particle " << a;
}

}  // namespace
