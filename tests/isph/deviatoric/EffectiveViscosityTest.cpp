// The effective viscosity of each material particle and the deviatoric stress τ = 2 η D
// (EffectiveViscosity.hpp), 2D, on a 10 × 10 lattice block of material (dx = 0.01 m, height
// H = 0.1 m) on a wall row with one dummy row below (LatticeBlockOnWallForTest.hpp). The
// strain rate is set by hand (a simple shear D_xy = |γ̇|/2 of a different |γ̇| at every
// particle), the pressure hydrostatic, p = ρ g (H − y):
//  - sand (rigidPlastic, φ = 30°, the paper's Eq. 3): η = sin φ (p + ½ ρ g dx) / |γ̇|, so that
//    the shear stress τ_xy = η |γ̇| is the strength whatever the shear rate; η is capped by
//    etaMax in the rigid limit (|γ̇| → 0, or 0) and floored by etaMin (a fast shear); p < 0
//    (tension) leaves the half layer's strength alone;
//  - water (newtonian): η = ρ ν whatever p and |γ̇|;
//  - each particle takes its own material's model; the walls and dummies get η = 0 and τ = 0;
//  - the value returned is the largest η/ρ (the explicit viscous time-step limit).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "LatticeBlockOnWallForTest.hpp"
#include "MaterialTableForTest.hpp"
#include "isph/deviatoric/EffectiveViscosity.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01, H = 0.1, g = 9.81, etaMax = 3000, etaMin = 5;
constexpr int n = 10;
constexpr double rhoSand = 2000, rhoWater = 1000, nu = 1e-6;
const double sinPhi = std::sin(30 * std::numbers::pi / 180);
const std::string materialsText =
    "sand { model rigidPlastic; rho 2000; phi 30; etaMax 3000; etaMin 5; } "
    "water { model newtonian; rho 1000; nu 1e-6; }";

// The strength sin φ (p + ½ ρ g dx) of the sand (Eq. 3 with the half layer of the model's header).
double strength(double p) { return sinPhi * (std::max(p, 0.0) + 0.5 * rhoSand * g * dx); }

struct Block {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  std::unique_ptr<MaterialTable> materials =
      test::materialTable("EffectiveViscosityTest", materialsText, {"sand", "water"});
  ParticleSystem ps = test::latticeBlockOnWall(*kernel, n, dx, rhoSand, 1);
  StrainRate strain;
  std::vector<double> eta;

  // `waterColumns`: the lattice columns i ≥ n − waterColumns are water, the others sand.
  explicit Block(int waterColumns = 0) {
    (*materials)[0].adaptToScene(SceneScales{H, g, dx});  // the half layer ½ ρ g dx
    ps.cloud.material.assign(ps.size(), -1);
    ps.cloud.p.assign(ps.size(), 0.0);
    strain.D.assign(ps.size(), SymmTensor::Zero());
    strain.shearRate.assign(ps.size(), 0.0);
    for (std::size_t a = 0; a < ps.nMaterial; ++a) {
      const bool isWater = static_cast<int>(a % n) >= n - waterColumns;
      ps.cloud.material[a] = isWater ? 1 : 0;
      ps.rho[a] = isWater ? rhoWater : rhoSand;
      ps.cloud.p[a] = ps.rho[a] * g * (H - ps.cloud.positions[a].y());
      shear(a, 0.5 + 0.1 * static_cast<double>(a));  // 0.5 to 10.4 1/s
    }
  }
  void shear(std::size_t a, double rate) {
    strain.shearRate[a] = rate;
    strain.D[a] << 0, rate / 2, 0, 0, 0, 0;
  }
  double update() { return effectiveViscosity(ps, *materials, strain, eta); }
};

// η = sin φ (p + ½ ρ g dx)/|γ̇| at every particle, between etaMin and etaMax here (from 9.4 to
// 1962 Pa s); measured relative error 0 (the same operations). The largest η/ρ, 0.981 m²/s, is
// the bottom row's slowest particle's.
TEST(EffectiveViscosity, TheYieldingSandHasTheViscosityOfItsStrengthOverItsShearRate) {
  Block b;
  const double maxNu = b.update();
  ASSERT_EQ(b.eta.size(), b.ps.size());
  double worst = 0, expectedMaxNu = 0, least = 1e300, most = 0;
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    const double expected = strength(b.ps.cloud.p[a]) / b.strain.shearRate[a];
    worst = std::max(worst, std::abs(b.eta[a] / expected - 1));
    expectedMaxNu = std::max(expectedMaxNu, expected / rhoSand);
    least = std::min(least, expected), most = std::max(most, expected);
  }
  std::printf(
      "sand: eta from %.4g to %.4g Pa s, largest relative error %.3g; largest eta/rho %.4g m^2/s\n",
      least, most, worst, maxNu);
  ASSERT_GT(least, etaMin);
  ASSERT_LT(most, etaMax);
  EXPECT_LT(worst, 1e-15);
  EXPECT_NEAR(maxNu, expectedMaxNu, 1e-15 * expectedMaxNu);
  for (std::size_t a = b.ps.nMaterial; a < b.ps.size(); ++a)
    EXPECT_EQ(b.eta[a], 0.0) << "wall or dummy " << a;
}

// The regularisation: at rest (|γ̇| = 0) and in a creep slower than strength/etaMax η = etaMax;
// a shear faster than strength/etaMin gives η = etaMin; under tension (p < 0) the strength
// is the half layer's, sin φ ½ ρ g dx = 49.05 Pa. The largest η/ρ is then etaMax/ρ.
TEST(EffectiveViscosity, TheRigidLimitIsCappedByEtaMaxAndAFastShearFlooredByEtaMin) {
  Block b;
  const std::size_t resting = 5 * n + 5, creeping = 5 * n + 6, fast = 5 * n + 7, pulled = 5 * n + 8;
  b.shear(resting, 0);
  b.shear(creeping, 1e-3 * strength(b.ps.cloud.p[creeping]) / etaMax);
  b.shear(fast, 1e3 * strength(b.ps.cloud.p[fast]) / etaMin);
  b.ps.cloud.p[pulled] = -500;
  const double maxNu = b.update();
  EXPECT_EQ(b.eta[resting], etaMax);
  EXPECT_EQ(b.eta[creeping], etaMax);
  EXPECT_EQ(b.eta[fast], etaMin);
  const double halfLayer = sinPhi * 0.5 * rhoSand * g * dx;
  std::printf("strength under tension %.4g Pa (half layer %.4g Pa)\n",
              b.eta[pulled] * b.strain.shearRate[pulled], halfLayer);
  EXPECT_NEAR(b.eta[pulled] * b.strain.shearRate[pulled], halfLayer, 1e-12 * halfLayer);
  EXPECT_EQ(maxNu, etaMax / rhoSand);
}

// The block's right half water: its particles have η = ρ ν = 1e-3 Pa s whatever their
// pressure and shear rate, the sand's their own; the largest η/ρ is over both materials (the
// sand's, 0.981 m²/s, here; with the sand at rest in its rigid limit it would be 1.5).
TEST(EffectiveViscosity, EachParticleTakesItsOwnMaterialsViscosity) {
  Block b(n / 2);
  const double maxNu = b.update();
  double expectedMaxNu = 0;
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    if (b.ps.cloud.material[a] == 1) {
      EXPECT_EQ(b.eta[a], rhoWater * nu) << "water particle " << a;
      expectedMaxNu = std::max(expectedMaxNu, nu);
    } else {
      const double expected = strength(b.ps.cloud.p[a]) / b.strain.shearRate[a];
      EXPECT_NEAR(b.eta[a], expected, 1e-15 * expected) << "sand particle " << a;
      expectedMaxNu = std::max(expectedMaxNu, expected / rhoSand);
    }
  }
  EXPECT_NEAR(maxNu, expectedMaxNu, 1e-15 * expectedMaxNu);
}

// A water block alone: the largest η/ρ is ν (measured 9.9999999999999995e-07 m²/s, the double
// nearest 1e-6: ρ ν / ρ).
TEST(EffectiveViscosity, TheLargestKinematicViscosityOfWaterIsNu) {
  Block b(n);
  const double maxNu = b.update();
  std::printf("water: largest eta/rho %.17g m^2/s\n", maxNu);
  EXPECT_NEAR(maxNu, nu, 1e-15 * nu);
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a)
    EXPECT_EQ(b.eta[a], rhoWater * nu) << "particle " << a;
}

// τ = 2 η D: in the simple shear of each particle τ_xy = η |γ̇| = sin φ (p + ½ ρ g dx), the
// strength, whatever the shear rate (0.5 to 10.4 1/s here; measured relative error 2.2e-16, one
// rounding), and the other components 0; the walls and dummies carry no stress.
TEST(EffectiveViscosity, TheShearStressOfTheYieldingSandIsItsStrengthWhateverItsShearRate) {
  Block b;
  b.update();
  const std::vector<SymmTensor> tau = deviatoricStress(b.ps, b.strain, b.eta);
  ASSERT_EQ(tau.size(), b.ps.size());
  double worst = 0;
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    const double expected = strength(b.ps.cloud.p[a]);
    worst = std::max(worst, std::abs(tau[a][1] / expected - 1));
    EXPECT_EQ(tau[a][0], 0.0);
    EXPECT_EQ(tau[a][3], 0.0);
    EXPECT_EQ(tau[a][5], 0.0);
  }
  std::printf("sand: largest relative error of tau_xy against the strength %.3g\n", worst);
  EXPECT_LT(worst, 1e-15);
  for (std::size_t a = b.ps.nMaterial; a < b.ps.size(); ++a)
    EXPECT_EQ(tau[a], SymmTensor::Zero()) << "particle " << a;
}

}  // namespace
