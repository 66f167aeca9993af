// The deviatoric stress of elastic-plastic soil in the weakly-compressible method
// (ElasticPlasticStress with DruckerPragerElasticPlastic), 2D, Wendland C2 with h = 1.3 dx,
// dx = 0.01 m, on a 14 × 14 lattice block of `rods` (ρ 2650, φ 19.8°, no cohesion, E 0.84 MPa,
// ν 0.3; the interior: particles three spacings or more from the edges, whose supports are
// full): the plain SPH velocity gradient and the law's integration together, s = 2 G D dt for
// a simple shear below the yield surface and √J2 = 3 α_φ p (each particle's own p) beyond it,
// no stress for a rigid translation, the state across a reordering and a restart. The point law
// itself is tests/isph/materials/DruckerPragerElasticPlasticTest.cpp. Also the scene check and
// the speeds (elasticPlasticSpeeds) against K and G from E and ν.
#include "isph/deviatoric/ElasticPlasticStress.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "LatticeBlockForTest.hpp"
#include "MaterialTableForTest.hpp"
#include "core/Error.hpp"
#include "isph/materials/DruckerPragerElasticPlastic.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01, rho = 2650, E = 0.84e6, nu = 0.3;
constexpr int n = 14;
const std::string rods = "rods { model elasticPlastic; rho 2650; phi 19.8; cohesion 0; E 0.84e6; nu 0.3; }";

bool interior(std::size_t a) { return test::inInterior(a, n); }

double rootJ2(const SymmTensor& s) { return std::sqrt(0.5 * doubleDotSymm(s)); }

struct Block {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps = test::latticeBlock(*kernel, n, dx);
  std::unique_ptr<MaterialTable> materials = test::materialTable("ElasticPlasticStressTest", rods, {"rods"});

  explicit Block(double p) {
    const std::size_t count = ps.nMaterial;
    ps.rho.assign(count, rho);
    ps.cloud.U.assign(count, Vec3::Zero());
    ps.cloud.p.assign(count, p);
    ps.cloud.material.assign(count, 0);
  }
  const DruckerPragerElasticPlastic& law() const {
    return static_cast<const DruckerPragerElasticPlastic&>((*materials)[0]);
  }
  // Simple shear u = (γ̇ y, 0).
  void shear(double rate) {
    for (std::size_t a = 0; a < ps.nMaterial; ++a) ps.cloud.U[a] = Vec3(rate * ps.cloud.positions[a].y(), 0, 0);
  }
};

TEST(ElasticPlasticStress, ASimpleShearBelowYieldLoadsTheInteriorElastically) {
  Block b(1000);  // √J2 = G γ̇ dt = 3.2 Pa, far inside the surface 3 α_φ p = 332 Pa
  const double rate = 1.0, dt = 1e-5;
  b.shear(rate);
  ElasticPlasticStress stress;
  stress.initialise(b.ps, nullptr);
  stress.update(b.ps, *b.materials, dt);
  const double G = E / (2 * (1 + nu));
  const double expected = G * rate * dt;  // s = 2 G D dt, D_xy = γ̇/2
  double worstShear = 0, worstNormal = 0, worstSum = 0;
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    if (!interior(a)) continue;
    const SymmTensor& s = stress.deviatoric()[a];
    worstShear = std::max(worstShear, std::abs(s[1] / expected - 1));
    double latticeSum = 0;  // −Σ V_b F Δy²: the plain gradient's ∂u/∂y over γ̇ (1 for the continuous kernel)
    for (long k = b.ps.neighbours.start[a]; k < b.ps.neighbours.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const Vec3 d = b.ps.cloud.positions[a] - b.ps.cloud.positions[static_cast<std::size_t>(b.ps.neighbours.index[kk])];
      latticeSum -= dx * dx * b.ps.neighbours.F[kk] * d.y() * d.y();
    }
    worstSum = std::max(worstSum, std::abs(s[1] / (expected * latticeSum) - 1));
    worstNormal = std::max({worstNormal, std::abs(s[0]), std::abs(s[3]), std::abs(s[5]), std::abs(s[2]),
                            std::abs(s[4])});
  }
  // The plain gradient's lattice sum −Σ V_b F Δy² is 2.6 % short of 1: s_xy measured 2.6e-2
  // (relative) off G γ̇ dt in the interior, and G γ̇ dt times that sum up to rounding (measured
  // 4e-16); the normal and out-of-plane parts zero up to rounding (measured 6e-16 Pa).
  std::printf("simple shear: s_xy off by %.3g (relative) of G γ̇ dt = %.4g Pa, by %.3g of it times the lattice sum; "
              "other parts at most %.3g Pa\n", worstShear, expected, worstSum, worstNormal);
  EXPECT_LT(worstShear, 3e-2);
  EXPECT_LT(worstSum, 1e-12);
  EXPECT_LT(worstNormal, 1e-12 * expected);
}

TEST(ElasticPlasticStress, AShearBeyondYieldLeavesEachParticleOnTheSurfaceAtItsOwnPressure) {
  Block b(0);
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) b.ps.cloud.p[a] = 500 + 1e5 * b.ps.cloud.positions[a].y();
  const double rate = 100, dt = 1e-3;  // a trial √J2 of about G γ̇ dt = 3.2e4 Pa
  b.shear(rate);
  ElasticPlasticStress stress;
  stress.initialise(b.ps, nullptr);
  stress.update(b.ps, *b.materials, dt);
  double worst = 0;
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    const double strength = 3 * b.law().alphaPhi() * b.ps.cloud.p[a];  // k_c = 0
    worst = std::max(worst, std::abs(rootJ2(stress.deviatoric()[a]) / strength - 1));
    if (interior(a)) {
      EXPECT_GT(stress.deviatoric()[a][1], 0.0) << "the shear's sense, particle " << a;
    }
  }
  // Every particle (the edges' trial stresses are smaller but also beyond the surface): on it up
  // to rounding (measured 2.2e-16 relative).
  std::printf("beyond yield: sqrt(J2) off the surface by %.3g (relative)\n", worst);
  EXPECT_LT(worst, 1e-12);
}

TEST(ElasticPlasticStress, ARigidTranslationLoadsNothing) {
  Block b(1000);
  for (auto& u : b.ps.cloud.U) u = Vec3(0.4, -0.3, 0);
  ElasticPlasticStress stress;
  stress.initialise(b.ps, nullptr);
  stress.update(b.ps, *b.materials, 1e-3);
  // u_b − u_a = 0 in every pair, the edges included: exactly zero.
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    EXPECT_EQ(stress.deviatoric()[a], SymmTensor::Zero()) << "particle " << a;
  }
}

// Block plus two wall particles (for the state's size: walls and dummies carry no stress).
ParticleSystem withWalls(const ParticleSystem& block) {
  ParticleSystem ps = block;
  ps.cloud.positions.emplace_back(-0.5 * dx, 0.5 * dx, 0);
  ps.cloud.positions.emplace_back(-0.5 * dx, 1.5 * dx, 0);
  ps.nWall = 2;
  return ps;
}

SymmTensor tensor(double k) {
  SymmTensor s;
  s << k, 0.1 * k, 0, -0.5 * k, 0, -0.5 * k;
  return s;
}

// A written field of deviatoric stresses, a different one per particle.
std::vector<SymmTensor> distinctStresses(std::size_t n) {
  std::vector<SymmTensor> written(n);
  for (std::size_t a = 0; a < n; ++a) written[a] = tensor(double(a) + 1);
  return written;
}

TEST(ElasticPlasticStress, ARestartsWrittenStressIsTheStateAndTheWallsCarryNone) {
  Block b(1000);
  const ParticleSystem ps = withWalls(b.ps);
  const std::vector<SymmTensor> written = distinctStresses(ps.size());
  ElasticPlasticStress stress;
  stress.initialise(ps, &written);
  ASSERT_EQ(stress.deviatoric().size(), ps.size());
  for (std::size_t a = 0; a < ps.nMaterial; ++a) EXPECT_EQ(stress.deviatoric()[a], written[a]) << "particle " << a;
  for (std::size_t a = ps.nMaterial; a < ps.size(); ++a) EXPECT_EQ(stress.deviatoric()[a], SymmTensor::Zero());
  stress.initialise(ps, nullptr);  // a fresh start: an isotropic stress
  for (std::size_t a = 0; a < ps.size(); ++a) EXPECT_EQ(stress.deviatoric()[a], SymmTensor::Zero());
}

TEST(ElasticPlasticStress, TheStressFollowsTheReorderingOfTheMaterial) {
  Block b(1000);
  const ParticleSystem ps = withWalls(b.ps);
  const std::vector<SymmTensor> written = distinctStresses(ps.size());
  ElasticPlasticStress stress;
  stress.initialise(ps, &written);
  std::vector<int> order(ps.nMaterial);  // order[new] = old: reversed
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(ps.nMaterial - 1 - i);
  stress.permute(order);
  for (std::size_t i = 0; i < ps.nMaterial; ++i) {
    EXPECT_EQ(stress.deviatoric()[i], written[static_cast<std::size_t>(order[i])]) << "particle " << i;
  }
  for (std::size_t a = ps.nMaterial; a < ps.size(); ++a) EXPECT_EQ(stress.deviatoric()[a], SymmTensor::Zero());
}

TEST(ElasticPlasticStressSpeeds, TheBulkAndPWaveSpeedsFromEAndNu) {
  const auto materials = test::materialTable("ElasticPlasticSpeedsTest", rods, {"rods"});
  const auto [sound, wave] = elasticPlasticSpeeds(*materials, Method::wcsph);
  const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));  // 0.7 MPa, 0.323 MPa
  // Exact up to rounding: 16.25 m/s and 20.66 m/s.
  std::printf("rods: sqrt(K/rho) %.6g m/s, P wave %.6g m/s\n", sound, wave);
  EXPECT_NEAR(sound, std::sqrt(K / rho), 1e-12);
  EXPECT_NEAR(wave, std::sqrt((K + 4 * G / 3) / rho), 1e-12);
}

TEST(ElasticPlasticStressSpeeds, TheFastestOfTwoElasticPlasticMaterials) {
  const auto materials = test::materialTable(
      "ElasticPlasticSpeedsTest",
      rods + " stiff { model elasticPlastic; rho 2000; phi 30; E 4e6; nu 0.2; }", {"rods", "stiff"});
  const auto [sound, wave] = elasticPlasticSpeeds(*materials, Method::wcsph);
  const double K = 4e6 / (3 * 0.6), G = 4e6 / 2.4;  // the stiff material: both speeds the larger
  EXPECT_NEAR(sound, std::sqrt(K / 2000), 1e-12);
  EXPECT_NEAR(wave, std::sqrt((K + 4 * G / 3) / 2000), 1e-12);
}

TEST(ElasticPlasticStressSpeeds, NoElasticPlasticMaterialNoSpeedsAndNoError) {
  const auto materials = test::materialTable(
      "ElasticPlasticSpeedsTest", "water { model newtonian; rho 1000; nu 1e-6; } air { model inviscid; rho 1; }",
      {"water", "air"});
  for (const Method m : {Method::isph, Method::wcsph}) {
    const auto [sound, wave] = elasticPlasticSpeeds(*materials, m);
    EXPECT_EQ(sound, 0.0);
    EXPECT_EQ(wave, 0.0);
  }
}

TEST(ElasticPlasticStressSpeeds, ElasticPlasticBesideAnotherModelIsFatal) {
  const auto materials = test::materialTable(
      "ElasticPlasticSpeedsTest", rods + " water { model newtonian; rho 1000; nu 1e-6; }", {"rods", "water"});
  try {
    elasticPlasticSpeeds(*materials, Method::wcsph);
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    EXPECT_NE(std::string(e.what()).find("found 1 of 2 materials elasticPlastic"), std::string::npos) << e.what();
  }
}

TEST(ElasticPlasticStressSpeeds, ElasticPlasticWithTheProjectionMethodIsFatal) {
  const auto materials = test::materialTable("ElasticPlasticSpeedsTest", rods, {"rods"});
  try {
    elasticPlasticSpeeds(*materials, Method::isph);
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    EXPECT_NE(std::string(e.what()).find("the projection method"), std::string::npos) << e.what();
  }
}

}  // namespace
