// The rate of deformation (StrainRate.hpp): D = dev ½(∇u + ∇uᵀ), |γ̇| = √(2 D:D), 2D (plane
// strain), Wendland C2 with h = 1.3 dx, dx = 0.01 m, on a 10 × 10 lattice block of material
// (LatticeBlockForTest.hpp) and on the same block resting on a wall row at y = 0 with dummy rows
// below (LatticeBlockOnWallForTest.hpp). The correction's threshold is 0.05, below the
// determinant of a corner's quarter support (0.135, KernelGradientCorrectionTest), so that
// every particle of the block is renormalised and the linear fields below are differentiated
// exactly (up to rounding) at every particle, the edges and corners included:
//  - simple shear u = (U₀ + γ̇ y, V₀): D_xy = γ̇/2 alone, |γ̇| = γ̇;
//  - planar extension u = ε (x, −y): D = diag(ε, −ε, 0), |γ̇| = 2ε;
//  - uniaxial stretching u = (ε x, 0): only the deviatoric part, ε diag(2/3, −1/3, −1/3)
//    (plane strain keeps D_zz), |γ̇| = 2ε/√3;
//  - rigid rotation: D = 0;
//  - on the wall: a sliding (rigidPlastic, Coulomb) material ignores the walls, so a plug
//    sliding over them has D = 0; a sticking (newtonian) one shears against the wall
//    particles at rest, and with the walls in its renormalisation a shear that vanishes on the
//    wall is still exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "LatticeBlockForTest.hpp"
#include "LatticeBlockOnWallForTest.hpp"
#include "MaterialTableForTest.hpp"
#include "isph/discretisation/KernelGradientCorrection.hpp"
#include "isph/deviatoric/StrainRate.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01, minDeterminant = 0.05;
constexpr int n = 10;
const std::string sand = "sand { model rigidPlastic; rho 2000; phi 30; }";
const std::string water = "water { model newtonian; rho 1000; nu 1e-6; }";

using Field = std::function<Vec3(const Vec3&)>;

// D in OpenFOAM order xx xy xz yy yz zz.
SymmTensor symm(double xx, double xy, double yy, double zz) {
  SymmTensor s;
  s << xx, xy, 0, yy, 0, zz;
  return s;
}

struct Case {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  std::unique_ptr<MaterialTable> materials;
  ParticleSystem ps;
  KernelGradientCorrection L;
  StrainRate strain;

  // `walls`: -1 for the free block, else the block on a wall row with that many dummy rows.
  Case(const std::string& material, const std::vector<std::string>& names, int walls = -1) {
    materials = test::materialTable("StrainRateTest", material, names);
    ps = walls < 0 ? test::latticeBlock(*kernel, n, dx)
                   : test::latticeBlockOnWall(*kernel, n, dx, 1000, walls);
    ps.cloud.material.assign(ps.size(), -1);
    std::fill_n(ps.cloud.material.begin(), ps.nMaterial, 0);
    ps.cloud.U.assign(ps.size(), Vec3::Zero());
    L.update(ps, true, minDeterminant);
  }
  void move(const Field& u) {
    for (std::size_t a = 0; a < ps.nMaterial; ++a) ps.cloud.U[a] = u(ps.cloud.positions[a]);
  }
  void compute() { strain.compute(ps, *materials, L, minDeterminant); }
  // The largest |D − expected| and ||γ̇| − expected| over the material particles.
  std::pair<double, double> errors(const SymmTensor& D, double shearRate) const {
    double dError = 0, rateError = 0;
    for (std::size_t a = 0; a < ps.nMaterial; ++a) {
      dError = std::max(dError, (strain.D[a] - D).cwiseAbs().maxCoeff());
      rateError = std::max(rateError, std::abs(strain.shearRate[a] - shearRate));
    }
    return {dError, rateError};
  }
};

// Measured: |D − D_exact| up to 1.7e-15 1/s and ||γ̇| − γ̇| 3.3e-15 1/s with γ̇ = 2 1/s
// (rounding), for both materials (no walls: the same sums).
TEST(StrainRate, SimpleShearHasTheShearRateOfItsVelocityGradient) {
  constexpr double rate = 2.0;
  for (const auto& [material, name] : {std::pair{sand, "sand"}, std::pair{water, "water"}}) {
    Case c(material, {name});
    c.move([](const Vec3& x) { return Vec3(0.3 + rate * x.y(), -0.1, 0); });
    c.compute();
    const auto [dError, rateError] = c.errors(symm(0, rate / 2, 0, 0), rate);
    std::printf("%s, simple shear: |D error| %.3g 1/s, |shear rate error| %.3g 1/s\n", name, dError,
                rateError);
    EXPECT_LT(dError, 1e-13 * rate) << name;
    EXPECT_LT(rateError, 1e-13 * rate) << name;
  }
}

// Isochoric: D is its own deviatoric part. Measured errors 1.8e-15 (D) and 3.6e-15 1/s
// (|γ̇|) with ε = 1.5 1/s.
TEST(StrainRate, PlanarExtensionStretchesAlongXAndShortensAlongY) {
  constexpr double eps = 1.5;
  Case c(sand, {"sand"});
  c.move([](const Vec3& x) { return Vec3(eps * x.x(), -eps * x.y(), 0); });
  c.compute();
  const auto [dError, rateError] = c.errors(symm(eps, 0, -eps, 0), 2 * eps);
  std::printf("planar extension: |D error| %.3g 1/s, |shear rate error| %.3g 1/s\n", dError,
              rateError);
  EXPECT_LT(dError, 1e-13 * eps);
  EXPECT_LT(rateError, 1e-13 * eps);
}

// Not isochoric: the trace ε/3 comes off all three diagonal entries, D_zz = −ε/3 included
// (plane strain). Measured errors 1.3e-15 (D) and 2.0e-15 1/s (|γ̇|) with ε = 1.5 1/s.
TEST(StrainRate, UniaxialStretchingKeepsOnlyTheDeviatoricPart) {
  constexpr double eps = 1.5;
  Case c(water, {"water"});
  c.move([](const Vec3& x) { return Vec3(eps * x.x(), 0, 0); });
  c.compute();
  const auto [dError, rateError] =
      c.errors(symm(2 * eps / 3, 0, -eps / 3, -eps / 3), 2 * eps / std::sqrt(3.0));
  std::printf("uniaxial stretching: |D error| %.3g 1/s, |shear rate error| %.3g 1/s\n", dError,
              rateError);
  EXPECT_LT(dError, 1e-13 * eps);
  EXPECT_LT(rateError, 1e-13 * eps);
}

// u = ω × (x − x_c): ∇u is antisymmetric, D = 0 (measured |D| 1.8e-15, |γ̇| 3.6e-15 1/s with
// ω = 3 rad/s). The field is passed to compute() while the particles' own velocity is a simple shear,
// which the overload without a field sees (|γ̇| = 2 1/s).
TEST(StrainRate, ARigidRotationDoesNotDeform) {
  constexpr double omega = 3.0;
  const Vec3 centre(0.04, 0.07, 0);
  Case c(water, {"water"});
  c.move([](const Vec3& x) { return Vec3(2.0 * x.y(), 0, 0); });
  std::vector<Vec3> u(c.ps.nMaterial);
  for (std::size_t a = 0; a < c.ps.nMaterial; ++a) {
    const Vec3 r = c.ps.cloud.positions[a] - centre;
    u[a] = Vec3(-omega * r.y(), omega * r.x(), 0);
  }
  c.strain.compute(c.ps, *c.materials, c.L, minDeterminant, u);
  const auto [dError, rateError] = c.errors(SymmTensor::Zero(), 0);
  std::printf("rigid rotation: largest |D| %.3g 1/s, largest shear rate %.3g 1/s\n", dError,
              rateError);
  EXPECT_LT(dError, 1e-13 * omega);
  EXPECT_LT(rateError, 1e-13 * omega);
  c.compute();
  EXPECT_LT(c.errors(symm(0, 1, 0, 0), 2).second, 1e-13) << "the particles' own velocity, a shear";
}

// A plug u = (0.5 m/s, 0) over a wall (two dummy rows), all at rest. Sand slides on walls:
// they are not in its sums, D = 0 everywhere (measured exactly 0: u_b − u_a = 0 for all
// material pairs). Water sticks: the rows within the support of the wall or the dummies
// (y = 0.5, 1.5, 2.5 dx) shear, D_xy > 0 (the velocity grows away from the wall); measured
// |γ̇| dx / U up to 0.73, 0.17 and 1.8e-4 in the three rows; the rows above do not shear (0).
TEST(StrainRate, ASlidingMaterialIgnoresTheWallsAndAStickingOneShearsAgainstThem) {
  constexpr double U = 0.5;
  Case sliding(sand, {"sand"}, 2), sticking(water, {"water"}, 2);
  for (Case* c : {&sliding, &sticking}) {
    c->move([&](const Vec3&) { return Vec3(U, 0, 0); });
    c->compute();
  }
  EXPECT_EQ(sliding.errors(SymmTensor::Zero(), 0), std::make_pair(0.0, 0.0))
      << "the sand plug slides undeformed";
  double rowRate[n] = {};
  for (std::size_t a = 0; a < sticking.ps.nMaterial; ++a) {
    const auto j = a / n;
    rowRate[j] = std::max(rowRate[j], sticking.strain.shearRate[a]);
    if (j < 3) {
      EXPECT_GT(sticking.strain.D[a][1], 0.0) << "water particle " << a << " next to the wall";
    } else {
      EXPECT_EQ(sticking.strain.shearRate[a], 0.0)
          << "water particle " << a << " beyond the wall's reach";
    }
  }
  std::printf("water plug over the wall: largest |shear rate| dx / U by row: %.3g %.3g %.3g %.3g\n",
              rowRate[0] * dx / U, rowRate[1] * dx / U, rowRate[2] * dx / U, rowRate[3] * dx / U);
  EXPECT_GT(rowRate[0], 0.5 * U / dx) << "the bottom row shears over half a spacing";
  for (std::size_t a = sticking.ps.nMaterial; a < sticking.ps.size(); ++a) {
    EXPECT_EQ(sticking.strain.D[a], SymmTensor::Zero()) << "wall or dummy " << a;
    EXPECT_EQ(sticking.strain.shearRate[a], 0.0) << "wall or dummy " << a;
  }
}

// A shear u = (γ̇ y, 0) that vanishes on the wall row y = 0 (no dummies, so the walls at rest
// are on the linear field): the sticking material sums over the walls and renormalises with
// their moment, the sliding one over the material alone; both exact at every particle
// (measured errors 5.6e-16 (D) and 1.1e-15 1/s (|γ̇|) for both, γ̇ = 2 1/s).
TEST(StrainRate, AShearThatVanishesOnTheWallIsExactForBothContacts) {
  constexpr double rate = 2.0;
  for (const auto& [material, name] : {std::pair{sand, "sand"}, std::pair{water, "water"}}) {
    Case c(material, {name}, 0);
    c.move([](const Vec3& x) { return Vec3(rate * x.y(), 0, 0); });
    c.compute();
    const auto [dError, rateError] = c.errors(symm(0, rate / 2, 0, 0), rate);
    std::printf(
        "%s, shear vanishing on the wall: |D error| %.3g 1/s, |shear rate error| %.3g 1/s\n", name,
        dError, rateError);
    EXPECT_LT(dError, 1e-13 * rate) << name;
    EXPECT_LT(rateError, 1e-13 * rate) << name;
  }
}

// The contact is each particle's own material's: the block's left half sand, its right half
// water, a plug over the wall. The sand particles stay undeformed (0 exactly), the water
// particles of the bottom row shear (as above).
TEST(StrainRate, EachParticleCountsTheWallsByItsOwnMaterial) {
  constexpr double U = 0.5;
  Case c(sand + " " + water, {"sand", "water"}, 2);
  for (std::size_t a = 0; a < c.ps.nMaterial; ++a) c.ps.cloud.material[a] = a % n < n / 2 ? 0 : 1;
  c.move([&](const Vec3&) { return Vec3(U, 0, 0); });
  c.compute();
  for (std::size_t a = 0; a < c.ps.nMaterial; ++a) {
    if (c.ps.cloud.material[a] == 0) {
      EXPECT_EQ(c.strain.shearRate[a], 0.0) << "sand particle " << a;
    } else if (a < n) {
      EXPECT_GT(c.strain.shearRate[a], 0.5 * U / dx) << "water particle " << a << " on the wall";
    }
  }
}

}  // namespace
