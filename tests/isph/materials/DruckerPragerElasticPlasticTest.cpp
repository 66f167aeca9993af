// The elastic-plastic Drucker-Prager model (Bui et al. 2008) as the weakly-compressible method
// integrates it: elastic below the yield surface, a trial stress outside returned onto it, the
// drained simple-shear limit at the Drucker-Prager slope, the Jaumann rotation, the moduli and
// the dictionary errors. All exact relations: tolerances are round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "isph/materials/DruckerPragerElasticPlastic.hpp"

namespace {

using namespace isph;
constexpr double deg = std::numbers::pi / 180.0;

DruckerPragerElasticPlastic soil(const std::string& entries) {
  const Dictionary d = Dictionary::parse("model elasticPlastic; rho 2650; " + entries, "materialProperties");
  return DruckerPragerElasticPlastic("rods", d);
}

double rootJ2(const SymmTensor& s) { return std::sqrt(0.5 * doubleDotSymm(s)); }

// Simple shear u = (γ̇ y, 0): ∇u has (x, y) = γ̇.
Eigen::Matrix3d simpleShear(double rate) {
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  g(0, 1) = rate;
  return g;
}

TEST(DruckerPragerElasticPlastic, ModuliAndWaveSpeedsFromEAndNu) {
  const auto m = soil("phi 19.8; E 0.84e6; nu 0.3;");
  EXPECT_NEAR(m.bulkModulus(), 0.84e6 / (3 * 0.4), 1e-6);
  EXPECT_NEAR(m.shearModulus(), 0.84e6 / 2.6, 1e-6);
  EXPECT_NEAR(m.bulkSpeed(), std::sqrt(0.7e6 / 2650), 1e-9);
  EXPECT_NEAR(m.waveSpeed(), std::sqrt((0.7e6 + 4.0 / 3.0 * 0.84e6 / 2.6) / 2650), 1e-9);
  const double t = std::tan(19.8 * deg);
  EXPECT_NEAR(m.alphaPhi(), t / std::sqrt(9 + 12 * t * t), 1e-15);
  EXPECT_EQ(m.kc(), 0.0);
  EXPECT_EQ(m.wallContact(), WallContact::coulombFriction);
  EXPECT_TRUE(m.integratesStress());
}

// Below the surface the update is the elastic one: s_xy = G γ̇ dt (s = 2 G ė', ė_xy = γ̇/2,
// and the spin of simple shear does not act on s = 0).
TEST(DruckerPragerElasticPlastic, ElasticBelowTheYieldSurface) {
  const auto m = soil("phi 30; E 1e6; nu 0.25;");
  const double p = 1000, rate = 1.0, dt = 1e-5;
  const SymmTensor s = m.updateDeviatoric(SymmTensor::Zero(), p, simpleShear(rate), dt);
  EXPECT_NEAR(s[1], m.shearModulus() * rate * dt, 1e-12);
  EXPECT_NEAR(s[0] + s[3] + s[5], 0.0, 1e-12);
  EXPECT_LT(m.yieldFunction(s, p), 0.0);
}

// A trial stress outside the surface returns onto it (f = 0), along its own direction.
TEST(DruckerPragerElasticPlastic, ATrialStressOutsideReturnsOntoTheSurface) {
  const auto m = soil("phi 30; E 1e6; nu 0.25;");
  const double p = 1000;
  SymmTensor trial;
  trial << 800, 600, 0, -500, 0, -300;
  ASSERT_GT(m.yieldFunction(trial, p), 0.0);
  const SymmTensor s = m.returnToYieldSurface(trial, p);
  EXPECT_NEAR(m.yieldFunction(s, p), 0.0, 1e-9);
  EXPECT_NEAR(rootJ2(s), 3 * m.alphaPhi() * p, 1e-9);
  const double scale = s[0] / trial[0];
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(s[i], scale * trial[i], 1e-9) << "component " << i;
  // Inside: unchanged.
  const SymmTensor small = 0.01 * trial;
  EXPECT_EQ(m.returnToYieldSurface(small, p), small);
}

// Shearing on at a fixed pressure: the shear stress rises elastically, then stays at the
// Drucker-Prager slope, |s_xy| = √J2 = 3 α_φ p (c = 0), the plane-strain fit's strength.
TEST(DruckerPragerElasticPlastic, SimpleShearSaturatesAtTheDruckerPragerSlope) {
  const auto m = soil("phi 30; E 1e6; nu 0.25;");
  const double p = 2000, rate = 0.5, dt = 1e-4;
  SymmTensor s = SymmTensor::Zero();
  for (int i = 0; i < 2000; ++i) s = m.updateDeviatoric(s, p, simpleShear(rate), dt);
  EXPECT_NEAR(rootJ2(s), 3 * m.alphaPhi() * p, 1e-9 * p);
  EXPECT_NEAR(m.yieldFunction(s, p), 0.0, 1e-9 * p);
  EXPECT_GT(s[1], 0.9 * rootJ2(s));  // mostly the shear component (the spin turns a little into s_xx, s_yy)
}

// No pressure and no cohesion: no strength, the deviatoric stress vanishes; cohesion c gives
// √J2 = k_c at p = 0.
TEST(DruckerPragerElasticPlastic, StrengthAtZeroPressureIsTheCohesionsOnly) {
  SymmTensor trial = SymmTensor::Zero();
  trial[1] = 5000;
  EXPECT_EQ(soil("phi 30; E 1e6; nu 0.25;").returnToYieldSurface(trial, 0.0), SymmTensor::Zero());
  const auto cohesive = soil("phi 30; cohesion 1000; E 1e6; nu 0.25;");
  EXPECT_NEAR(cohesive.kc(), 3000 / std::sqrt(9 + 12 * std::pow(std::tan(30 * deg), 2)), 1e-9);
  EXPECT_NEAR(rootJ2(cohesive.returnToYieldSurface(trial, 0.0)), cohesive.kc(), 1e-9);
}

// A rigid rotation (spin Ω) turns s with the material: ds/dt = ω s − s ω, and √J2 is kept
// to first order. s = diag(σ1, −σ1, 0) under u = (−Ω y, Ω x): ds_xy/dt = 2 Ω σ1.
TEST(DruckerPragerElasticPlastic, JaumannRateTurnsTheStressWithARigidRotation) {
  const auto m = soil("phi 45; E 1e6; nu 0.25;");
  const double omega = 2.0, dt = 1e-6, s1 = 100, p = 1e4;
  Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
  g(0, 1) = -omega, g(1, 0) = omega;
  SymmTensor s;
  s << s1, 0, 0, -s1, 0, 0;
  const SymmTensor next = m.updateDeviatoric(s, p, g, dt);
  EXPECT_NEAR(next[1], 2 * omega * s1 * dt, 1e-12);
  EXPECT_NEAR(next[0], s1, 1e-12);
  EXPECT_NEAR(rootJ2(next), rootJ2(s), 1e-6 * rootJ2(s));
}

TEST(DruckerPragerElasticPlastic, BadEntriesAreFatal) {
  EXPECT_THROW(soil("phi 95; E 1e6; nu 0.3;"), FatalError);
  EXPECT_THROW(soil("phi 30; E -1; nu 0.3;"), FatalError);
  EXPECT_THROW(soil("phi 30; E 1e6; nu 0.5;"), FatalError);
  EXPECT_THROW(soil("phi 30; cohesion -5; E 1e6; nu 0.3;"), FatalError);
  EXPECT_THROW(soil("phi 30; nu 0.3;"), FatalError);  // E missing
  try {
    soil("phi 30; E 1e6; nu 0.7;");
    FAIL() << "no error";
  } catch (const FatalError& e) {
    const std::string what = e.report();
    EXPECT_NE(what.find("materialProperties"), std::string::npos) << what;
    EXPECT_NE(what.find("nu"), std::string::npos) << what;
  }
}

}  // namespace
