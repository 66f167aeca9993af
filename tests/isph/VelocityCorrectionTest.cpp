// Eq. 11 in its two forms (VelocityCorrection.hpp), 2D, Wendland C2 with h = 1.3 dx, on a
// 12 × 12 lattice block of material at a uniform 1000 Pa, u* = 0, one interior particle moved
// to half a spacing from its right-hand neighbour (a pair, as a thin granular stream forms
// them; doc/notes/granularSlope.md):
//  - the renormalised difference form L_a Σ V_b (p_b − p_a)∇W sees no gradient in a uniform
//    pressure, so nothing moves, the pair included;
//  - the paper's symmetric form Σ m_b (p_a/ρ_a² + p_b/ρ_b²)∇W pushes the pair apart along
//    its line, and conserves momentum: the forces of the pairs cancel (no walls here).
#include <gtest/gtest.h>

#include <cmath>

#include "LatticeBlockForTest.hpp"
#include "isph/KernelGradientCorrection.hpp"
#include "isph/VelocityCorrection.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01, rho = 1000, p0 = 1000, dt = 1e-3;
constexpr int n = 12;
constexpr int moved = 5 * n + 5, partner = 5 * n + 6;  // lattice particles (5, 5) and (6, 5)

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

TEST(VelocityCorrection, TheSymmetricFormPushesAPairApartAndConservesMomentum) {
  PairedBlock b;
  const std::vector<Vec3> ustar(b.ps.nMaterial, Vec3::Zero());
  correctVelocity(b.ps, b.L, ustar, Vec3(0, -9.81, 0), dt, b.kernel.get());
  const Vec3 line = (b.ps.cloud.positions[partner] - b.ps.cloud.positions[moved]).normalized();
  const double separating = (b.ps.cloud.U[partner] - b.ps.cloud.U[moved]).dot(line);
  // The pair's mutual force alone: 2 m V p0/ρ |∇W(dx/2)| each way, over dt.
  const double expected = 2 * 2 * dt * dx * dx * p0 / rho * std::abs(b.kernel->dWdr(0.5 * dx));
  std::printf("pair separating at %.4g m/s (their mutual force alone: %.4g m/s)\n", separating, expected);
  EXPECT_GT(separating, 0.5 * expected);
  Vec3 momentum = Vec3::Zero();
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) momentum += b.ps.cloud.mass[a] * b.ps.cloud.U[a];
  EXPECT_LT(momentum.norm(), 1e-12 * rho * dx * dx) << "the pair forces do not cancel";
}

}  // namespace
