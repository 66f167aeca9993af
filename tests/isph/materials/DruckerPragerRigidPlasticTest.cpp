// The rigid-plastic Drucker-Prager model (the paper's Eq. 3) and the equivalent friction of
// Eq. 12: the norm convention pinned by simple shear, the regularisation bounds, the
// dictionary errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "isph/deviatoric/StrainRate.hpp"
#include "isph/materials/DruckerPragerRigidPlastic.hpp"
#include "isph/materials/EquivalentFriction.hpp"

namespace {

using namespace isph;
constexpr double deg = std::numbers::pi / 180.0;

std::unique_ptr<MaterialModel> sand(const std::string& entries) {
  const Dictionary d = Dictionary::parse("model rigidPlastic; rho 2000; " + entries, "materialProperties");
  auto m = makeMaterialModel("sand", d);
  m->adaptToScene({.height = 0.1, .gravity = 9.81, .spacing = 0.0});  // no half-layer term
  return m;
}

// Simple shear u = (γ̇ y, 0): D' has D_xy = γ̇/2, |γ̇| = γ̇; s = 2 η D' must give
// |s_xy| = p sin φ and √(½ s:s) = p sin φ for any rate above the regularisation.
TEST(DruckerPragerRigidPlastic, SimpleShearStressIsPSinPhi) {
  const auto m = sand("phi 30;");
  const double p = 5000;
  for (double rate : {0.1, 1.0, 100.0}) {
    SymmTensor D = SymmTensor::Zero();
    D[1] = rate / 2;  // xy
    ASSERT_NEAR(shearRateMagnitude(D), rate, 1e-12);
    const SymmTensor s = 2.0 * m->viscosity(p, shearRateMagnitude(D)) * D;
    const double secondInvariant = std::sqrt(0.5 * (2 * s[1] * s[1]));
    EXPECT_NEAR(std::abs(s[1]), p * std::sin(30 * deg), 1e-9 * p) << "rate " << rate;
    EXPECT_NEAR(secondInvariant, p * std::sin(30 * deg), 1e-9 * p);
  }
}

TEST(DruckerPragerRigidPlastic, ViscosityIsBoundedByEtaMinAndEtaMax) {
  const auto m = sand("phi 30; etaMax 1e5; etaMin 2;");
  EXPECT_DOUBLE_EQ(m->viscosity(1000, 0.0), 1e5);   // at rest: the rigid limit's cap
  EXPECT_DOUBLE_EQ(m->viscosity(1000, 1e-6), 1e5);
  EXPECT_DOUBLE_EQ(m->viscosity(0, 10.0), 2.0);     // no pressure, no strength: the floor
  EXPECT_DOUBLE_EQ(m->viscosity(-50, 10.0), 2.0);   // no tension
  EXPECT_DOUBLE_EQ(m->maxViscosity(), 1e5);
  EXPECT_EQ(m->wallContact(), WallContact::coulombFriction);
}

TEST(DruckerPragerRigidPlastic, DefaultCapFollowsTheScene) {
  const auto m = sand("phi 30;");
  EXPECT_NEAR(m->maxViscosity(), 1e4 * 2000 * std::sqrt(9.81 * 1e-3), 1e-6);  // 1e4 ρ √(g H³), H = 0.1
}

TEST(DruckerPragerRigidPlastic, HalfALayerOfStrengthAtTheFreeSurface) {
  const Dictionary d = Dictionary::parse("model rigidPlastic; rho 2000; phi 30;", "materialProperties");
  auto m = makeMaterialModel("sand", d);
  m->adaptToScene({.height = 0.1, .gravity = 10.0, .spacing = 0.01});
  // p = 0 on a surface particle: strength sin φ × ½ ρ g dx = 0.5 × 100 Pa.
  EXPECT_NEAR(m->viscosity(0.0, 1.0), 50.0, 1e-9);
}

TEST(DruckerPragerRigidPlastic, BadEntriesAreFatalWithTheKeyword) {
  EXPECT_THROW(sand("phi 95;"), FatalError);
  EXPECT_THROW(sand("phi 30; phiEquivalent 35;"), FatalError);
  EXPECT_THROW(sand("phi 30; phiEquivalent 20; waterTable { height 2; soilDepth 10; }"), FatalError);
  EXPECT_THROW(sand("phi 30; etaMax -1;"), FatalError);
  EXPECT_THROW(sand("phi 30; etaMax 1; etaMin 10;"), FatalError);
  EXPECT_THROW(sand("phi 30; waterTable { height 12; soilDepth 10; rhoWater 2000; }"), FatalError);
  try {
    sand("phi 95;");
  } catch (const FatalError& e) {
    EXPECT_NE(std::string(e.what()).find("phi"), std::string::npos) << e.what();
  }
}

// Eq. 12: sin φ_e = sin φ / (1 + u/p'). The paper's case 3 reports φ_e = 23.24° and 22.33°
// for φ' = 29°; their u/p' follow from Eq. 12 and must give those angles back.
TEST(EquivalentFriction, Equation12) {
  EXPECT_NEAR(equivalentFrictionAngle(29, 0.0), 29.0, 1e-12);
  for (double phiE : {23.24, 22.33}) {
    const double ratio = std::sin(29 * deg) / std::sin(phiE * deg) - 1.0;
    EXPECT_NEAR(equivalentFrictionAngle(29, ratio), phiE, 1e-9);
  }
  const auto m = sand("phi 29; phiEquivalent 23.24;");
  EXPECT_NEAR(dynamic_cast<const DruckerPragerRigidPlastic&>(*m).frictionCoefficient(), std::sin(23.24 * deg),
              1e-12);
}

// Infinite slope: u/p' = ρ_w h_w / (ρ z − ρ_w h_w), the slope angle cancels.
TEST(EquivalentFriction, InfiniteSlopeWaterTable) {
  EXPECT_NEAR(infiniteSlopePorePressureRatio({.height = 2, .soilDepth = 10, .rhoWater = 1000}, 2000),
              2000.0 / 18000.0, 1e-15);
  EXPECT_THROW(infiniteSlopePorePressureRatio({.height = 10, .soilDepth = 5, .rhoWater = 1000}, 2000),
               std::invalid_argument);
  const auto m = sand("phi 29; waterTable { height 2; soilDepth 10; }");
  const double expected = equivalentFrictionAngle(29, 2000.0 / 18000.0);
  EXPECT_NEAR(dynamic_cast<const DruckerPragerRigidPlastic&>(*m).phiEffective(), expected, 1e-12);
}

}  // namespace
