// The deviatoric stress of a step (ViscousStress.hpp): η of the state at the step start (time
// n), τ = 2 ηⁿ D(u) as it acted in the step, and τ asked for by a write. 2D, Wendland C2 with
// h = 1.3 dx, dx = 0.01 m, on a 10 × 10 lattice block of sand (rigidPlastic, φ = 30°, ρ =
// 2000 kg/m³, etaMax 3000 Pa s, H = 0.1 m; LatticeBlockForTest.hpp) under a hydrostatic
// pressure p = ρ g (H − y), in simple shears u = (γ̇ y, 0), which the strain rate
// differentiates exactly at every particle (threshold 0.05, below the corners' determinant:
// StrainRateTest). The strength S = sin φ (p + ½ ρ g dx) (Eq. 3) then gives:
//  - update(): η = S/γ̇ₙ at every particle, maxNu() = max η/ρ;
//  - keepActing(u*): τ_xy = ηⁿ γ̇* = S γ̇*/γ̇ₙ (the stress that acted with the semi-implicit
//    term), not S (the stress re-evaluated at u*); keepActing(null): τ_xy = S, of the state
//    at update() even if the particles' velocity changed since;
//  - tau(step) of the kept step returns the kept τ; of another step (a write before the
//    first step) 2 η D of the current state, with maxNu() unchanged and, before any update(),
//    η still unknown;
//  - an inviscid material has no τ.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "LatticeBlockForTest.hpp"
#include "MaterialTableForTest.hpp"
#include "isph/discretisation/KernelGradientCorrection.hpp"
#include "isph/deviatoric/ViscousStress.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01, H = 0.1, g = 9.81, rho = 2000, minDeterminant = 0.05;
constexpr int n = 10;
const double sinPhi = std::sin(30 * std::numbers::pi / 180);

double strength(double p) { return sinPhi * (p + 0.5 * rho * g * dx); }

struct Block {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  std::unique_ptr<MaterialTable> materials;
  ParticleSystem ps = test::latticeBlock(*kernel, n, dx);
  KernelGradientCorrection L;

  explicit Block(
      const std::string& material = "sand { model rigidPlastic; rho 2000; phi 30; etaMax 3000; }") {
    materials = test::materialTable("ViscousStressTest", material, {"sand"});
    (*materials)[0].adaptToScene(SceneScales{H, g, dx});
    ps.cloud.material.assign(ps.nMaterial, 0);
    ps.rho.assign(ps.nMaterial, rho);
    ps.cloud.p.resize(ps.nMaterial);
    for (std::size_t a = 0; a < ps.nMaterial; ++a)
      ps.cloud.p[a] = rho * g * (H - ps.cloud.positions[a].y());
    shear(ps.cloud.U, 2.0);
    L.update(ps, true, minDeterminant);
  }
  void shear(std::vector<Vec3>& u, double rate) const {
    u.resize(ps.nMaterial);
    for (std::size_t a = 0; a < ps.nMaterial; ++a)
      u[a] = Vec3(rate * ps.cloud.positions[a].y(), 0, 0);
  }
  // The largest |τ_xy/(factor S) − 1| and the largest |other component|/S.
  std::pair<double, double> errors(const std::vector<SymmTensor>& tau, double factor) const {
    double xy = 0, others = 0;
    for (std::size_t a = 0; a < ps.nMaterial; ++a) {
      const double S = strength(ps.cloud.p[a]);
      xy = std::max(xy, std::abs(tau[a][1] / (factor * S) - 1));
      SymmTensor rest = tau[a];
      rest[1] = 0;
      others = std::max(others, rest.cwiseAbs().maxCoeff() / S);
    }
    return {xy, others};
  }
};

// η = S/γ̇ with γ̇ = 2 1/s (from 49 to 981 Pa s, under etaMax): measured relative error 6.7e-16
// (the strain rate's rounding); maxNu() = the bottom row's η/ρ = 0.245 m²/s.
TEST(ViscousStress, UpdateGivesTheViscosityOfTheStateAndItsLargestOverDensity) {
  Block b;
  ViscousStress stress(b.ps, *b.materials, b.L, minDeterminant);
  EXPECT_FALSE(stress.known());
  stress.update();
  ASSERT_TRUE(stress.known());
  double worst = 0, maxNu = 0;
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    const double expected = strength(b.ps.cloud.p[a]) / 2.0;
    worst = std::max(worst, std::abs(stress.eta()[a] / expected - 1));
    maxNu = std::max(maxNu, expected / rho);
  }
  std::printf("eta of the state: largest relative error %.3g; maxNu %.4g m^2/s (expected %.4g)\n",
              worst, stress.maxNu(), maxNu);
  EXPECT_LT(worst, 1e-13);
  EXPECT_NEAR(stress.maxNu(), maxNu, 1e-13 * maxNu);
}

// The semi-implicit term solved for u*, a shear of 5 1/s, with ηⁿ of the state's 2 1/s: the
// stress that acted is τ_xy = ηⁿ · 5 = 2.5 S, not S (a stress re-evaluated at u*); η and
// maxNu() are still the state's. Measured: relative error 6.7e-16, other components 9.0e-16 S.
// tau() of the same step returns that τ, not one of the particles' current state.
TEST(ViscousStress, TheActingStressIsTheViscosityOfTheStateAtTheRateOfUStar) {
  Block b;
  ViscousStress stress(b.ps, *b.materials, b.L, minDeterminant);
  stress.update();
  const std::vector<double> eta = stress.eta();
  const double maxNu = stress.maxNu();
  std::vector<Vec3> ustar;
  b.shear(ustar, 5.0);
  stress.keepActing(&ustar, 7);
  const std::vector<SymmTensor>* tau = stress.tau(7);
  ASSERT_NE(tau, nullptr);
  ASSERT_EQ(tau->size(), b.ps.size());
  const auto [xy, others] = b.errors(*tau, 2.5);
  std::printf("tau of u*: relative error of tau_xy against 2.5 S %.3g, other components %.3g S\n",
              xy, others);
  EXPECT_LT(xy, 1e-13);
  EXPECT_LT(others, 1e-13);
  EXPECT_EQ(stress.eta(), eta) << "η is the state's (time n)";
  EXPECT_EQ(stress.maxNu(), maxNu);
}

// The explicit term (no u*): τ = 2 ηⁿ D(uⁿ), τ_xy = S, of the state update() saw, although the
// particles' velocity has been changed since to a shear of 5 1/s (measured relative error
// 0, other components 1.5e-16 S).
TEST(ViscousStress, TheExplicitStressIsTheStrengthOfTheStateAtUpdate) {
  Block b;
  ViscousStress stress(b.ps, *b.materials, b.L, minDeterminant);
  stress.update();
  b.shear(b.ps.cloud.U, 5.0);
  stress.keepActing(nullptr, 3);
  const auto [xy, others] = b.errors(*stress.tau(3), 1.0);
  std::printf("explicit tau: relative error of tau_xy against S %.3g, other components %.3g S\n",
              xy, others);
  EXPECT_LT(xy, 1e-13);
  EXPECT_LT(others, 1e-13);
}

// A write before the first step (no τ kept for step 0): τ = 2 η D of the state it reads, here
// a shear of 0.5 1/s after an update() at 2 1/s, so τ_xy = S again (η = S/0.5, up to 1962 Pa s);
// maxNu() stays the update()'s 0.245 m²/s although the state's η/ρ is now up to 0.98 m²/s.
// A later step's keepActing replaces it, and tau() of that step returns the new one.
TEST(ViscousStress, AWriteBeforeTheFirstStepSeesTheStateReadAndLeavesTheTimeStepAlone) {
  Block b;
  ViscousStress stress(b.ps, *b.materials, b.L, minDeterminant);
  stress.update();
  const double maxNu = stress.maxNu();
  b.shear(b.ps.cloud.U, 0.5);
  const auto [xy, others] = b.errors(*stress.tau(0), 1.0);
  const double stateMaxNu = *std::max_element(stress.eta().begin(), stress.eta().end()) / rho;
  std::printf(
      "tau before the first step: relative error %.3g, others %.3g S; maxNu %.4g m^2/s, the "
      "state's %.4g\n",
      xy, others, stress.maxNu(), stateMaxNu);
  EXPECT_LT(xy, 1e-13);
  EXPECT_LT(others, 1e-13);
  EXPECT_EQ(stress.maxNu(), maxNu) << "the time step does not depend on whether a write asked";
  EXPECT_GT(stateMaxNu, 3 * maxNu) << "(the state's η differs, or the test would not tell)";
  std::vector<Vec3> ustar;
  b.shear(ustar, 1.0);
  stress.keepActing(&ustar, 1);
  EXPECT_LT(b.errors(*stress.tau(1), 2.0).first, 1e-13) << "η = S/0.5 at the rate 1 1/s: 2 S";
}

// tau()'s promise that the largest η/ρ, and with it the time step, stays as it was, for a write
// before any update(): η stays unknown, so ParticleSolver::nextDeltaT keeps the models' bound
// (etaMax/ρ = 1.5 m²/s here) for the first step. (Before the fix known() turned true with
// maxNu() 0: no viscous limit. isphLandslideFoam writes only after a step, so no run reached it.)
TEST(ViscousStress, AWriteBeforeAnyUpdateLeavesTheViscosityUnknown) {
  Block b;
  ViscousStress stress(b.ps, *b.materials, b.L, minDeterminant);
  ASSERT_NE(stress.tau(0), nullptr);
  EXPECT_FALSE(stress.known()) << "known() with maxNu() " << stress.maxNu()
                               << ": the first step would have no viscous time-step limit";
}

// An inviscid material has no deviatoric stress: nothing to compute, no τ, η unknown.
TEST(ViscousStress, AnInviscidMaterialHasNoStress) {
  Block b("sand { model inviscid; rho 2000; }");
  ViscousStress stress(b.ps, *b.materials, b.L, minDeterminant);
  stress.update();
  EXPECT_FALSE(stress.known());
  stress.keepActing(nullptr, 1);
  EXPECT_EQ(stress.tau(1), nullptr);
  EXPECT_EQ(stress.tau(2), nullptr);
}

}  // namespace
