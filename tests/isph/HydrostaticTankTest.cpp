// Still water in an open tank (tutorials/validation/hydrostaticTank, coarse: 20 particles over
// the depth): the exact solution is U = 0 and p = ρ g × depth, for ever. The
// wall condition, the free-surface detection and the PPE must reproduce it to solver
// tolerance, and keep it: an unstable mode of the discretisation grows from round-off.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "CaseRunner.hpp"
#include "particles/CloudIO.hpp"

namespace {

using isph::test::CaseRunner;
using namespace isph;

// The normal force (4th column) of the last row of a sampleForces .dat file.
double lastNormalForce(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != '#') last = line;
  }
  std::istringstream row(last);
  double t = 0, fx = 0, fy = 0, fn = 0;
  row >> t >> fx >> fy >> fn;
  return fn;
}

// The tank at 20 particles over the depth run to `endTime`, written at `writeInterval`: both
// utilities succeed and no particle crosses a wall.
void runTank(CaseRunner& c, const std::string& endTime, const std::string& writeInterval) {
  c.set("system/particleMeshDict", "spacing", "0.02");
  c.set("system/controlDict", "endTime", endTime);
  c.set("system/controlDict", "writeInterval", writeInterval);
  ASSERT_EQ(c.run(PARTICLEMESH_EXE, "particleMesh"), 0);
  ASSERT_EQ(c.run(SOLVER_EXE, "isphLandslideFoam"), 0) << "see " << c.path() / "log.isphLandslideFoam";
  EXPECT_EQ(c.logValue("isphLandslideFoam", "Wall crossings in the run:"), "0");
}

TEST(HydrostaticTank, StaysAtRestWithTheHydrostaticPressureForTwoSeconds) {
  CaseRunner c("hydrostaticTank", "hydrostaticTank");
  ASSERT_NO_FATAL_FAILURE(runTank(c, "2", "1"));

  const ParticleCloud cloud = readCloud(c.path() / "2", "particles");
  const double rho = 1000, g = 9.81, H = 0.4;
  double ySurface = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] == 0) ySurface = std::max(ySurface, cloud.positions[i].y());
  }
  // Depth below the free surface as the solver holds it: p = 0 on the surface particles
  // (the paper's condition), which sit half a spacing below the top of the material; the
  // pressure is therefore ρ g dx/2 below ρ g × (depth from the top), and a wall force
  // ½ ρ g H² is low by about dx/H.
  const double surface = ySurface;
  double maxSpeed = 0, sumError2 = 0, sumExact2 = 0, minDev = 1e300, maxDev = -1e300;
  std::size_t n = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != 0) continue;
    ++n;
    maxSpeed = std::max(maxSpeed, cloud.U[i].norm());
    const double depth = surface - cloud.positions[i].y();
    const double exact = rho * g * depth;
    sumError2 += (cloud.p[i] - exact) * (cloud.p[i] - exact);
    sumExact2 += exact * exact;
    if (depth > 0.1 * H) {  // interior: the spread of p − ρ g depth (the "smooth stress" claim)
      minDev = std::min(minDev, (cloud.p[i] - exact) / (rho * g * H));
      maxDev = std::max(maxDev, (cloud.p[i] - exact) / (rho * g * H));
    }
  }
  const double l2 = std::sqrt(sumError2 / sumExact2);
  std::printf("L2 error of p %.3g%%, interior spread %.3g%%, peak speed %.3g m/s\n", 100 * l2,
              100 * (maxDev - minDev), maxSpeed);
  EXPECT_EQ(n, 400u);
  EXPECT_NEAR(ySurface, H - 0.01, 1e-9) << "the surface has moved";
  // Exact to the PPE's tolerance (1e-8): measured L2 2.4e-8 and spread 1.5e-8 here, 1.8e-9 to
  // 1.8e-8 and 2.8e-9 to 1.1e-8 in the tutorial's -test runs with other write intervals, peak
  // speeds 6e-10 to 1e-9 m/s. The bounds are 40-100 times that noise.
  EXPECT_LT(l2, 1e-6) << "L2 error of the pressure against rho g depth";
  EXPECT_LT(maxDev - minDev, 1e-6) << "spread of (p - rho g depth)/(rho g H) in the interior";
  EXPECT_LT(maxSpeed, 1e-7) << "peak speed [m/s]";
}

// Still water around a solid block standing on the bed (a box wall 0.1 m wide, x 0.15-0.25 m,
// frictionless) for 0.5 s, 20 particles over the depth; the exact state is the tank's, U = 0
// and p = ρ g × depth, with the same bounds as the tank's test above. The block out of the
// water (0.5 m high): exact (measured here: L2 1.2e-8, peak speed 1.7e-10 m/s, the tank's
// noise; the bounds are the tank test's).
// Under the water (0.2 m high) its top corners are convex corners under the material, and the
// water does not stay at rest: 0.016 m/s after one step, 0.78 m/s and p L2 44 % at 0.5 s
// (this test), p +1,222 Pa above the block after one step (doc/notes/threeD.md: the PPE's
// relaxation source reads the corner's wall layers as compression, and the wall safeguard
// moves the water beside a corner, 0.35 dx from the corner particle along its mean normal).
// Disabled: below the goal, the cause not fixed (the wall condition at convex corners: issue
// 48's and 49's ground).
void expectBlockedTankAtRest(const std::string& name, const std::string& blockHeight) {
  CaseRunner c("hydrostaticTank", name);
  ASSERT_NO_FATAL_FAILURE(c.replaceText(
      "system/particleMeshDict", "    bottom ",
      "    block  { type box; min (0.15 0 0); max (0.25 " + blockHeight + " 0); frictionAngle 0; }\n    bottom "));
  ASSERT_NO_FATAL_FAILURE(runTank(c, "0.5", "0.5"));
  const ParticleCloud cloud = readCloud(c.path() / "0.5", "particles");
  const double rho = 1000, g = 9.81, surface = 0.39;  // the top particles' centres (p = 0 there)
  double maxSpeed = 0, sumError2 = 0, sumExact2 = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != 0) continue;
    maxSpeed = std::max(maxSpeed, cloud.U[i].norm());
    const double exact = rho * g * (surface - cloud.positions[i].y());
    sumError2 += (cloud.p[i] - exact) * (cloud.p[i] - exact);
    sumExact2 += exact * exact;
  }
  const double l2 = std::sqrt(sumError2 / sumExact2);
  std::printf("L2 error of p %.3g%%, peak speed %.3g m/s\n", 100 * l2, maxSpeed);
  EXPECT_LT(l2, 1e-6) << "L2 error of the pressure against rho g depth";
  EXPECT_LT(maxSpeed, 1e-7) << "peak speed [m/s]";
}

TEST(HydrostaticTank, StaysAtRestBesideABlockOutOfTheWater) {
  expectBlockedTankAtRest("hydrostaticTankBlockOut", "0.5");
}

TEST(HydrostaticTank, DISABLED_StaysAtRestOverASubmergedBlock) {
  expectBlockedTankAtRest("hydrostaticTankBlockUnder", "0.2");
}

// The force on each vertical wall from the solver's wall pressures, sampled by sampleForces:
// the wall particles' hydrostatic pressures sum to ρ g (H² − 9 dx²)/2 per metre, second order
// in dx/H (−2.25 %, −0.5625 %, −0.1406 % at 20, 40 and 80 particles over the depth, the same to
// every printed digit in every run: the PPE's tolerance), checked to 1e-5 of ρ g H²/2.
class HydrostaticWallForce : public ::testing::TestWithParam<double> {};

TEST_P(HydrostaticWallForce, IsRhoGHSquaredOverTwo) {
  const double dx = GetParam(), rho = 1000, g = 9.81, H = 0.4;
  CaseRunner c("hydrostaticTank", "hydrostaticWallForce-" + std::to_string(dx));  // one folder per instance: ctest -j runs them at once
  c.set("system/particleMeshDict", "spacing", std::to_string(dx));
  c.set("system/controlDict", "endTime", "0.1");
  c.set("system/controlDict", "writeInterval", "0.1");
  ASSERT_EQ(c.run(PARTICLEMESH_EXE, "particleMesh"), 0);
  ASSERT_EQ(c.run(SOLVER_EXE, "isphLandslideFoam"), 0) << "see " << c.path() / "log.isphLandslideFoam";
  ASSERT_EQ(c.run(SAMPLEFORCES_EXE, "sampleForces", "-latestTime"), 0);
  for (const char* wall : {"left", "right"}) {
    const double fn = lastNormalForce(c.path() / "postProcessing/sampleForces/0.1" / (std::string(wall) + ".dat"));
    const double exact = 0.5 * rho * g * H * H;
    std::printf("dx %g, %s wall: %.2f N/m, exact %.2f (%+.2f%%)\n", dx, wall, fn, exact, 100 * (fn / exact - 1));
    EXPECT_NEAR(fn / exact, 1.0 - 9 * dx * dx / (H * H), 1e-5) << wall << " wall force against rho g (H^2 - 9 dx^2)/2";
  }
}

INSTANTIATE_TEST_SUITE_P(FortyAndEightyOverTheDepth, HydrostaticWallForce, ::testing::Values(0.01, 0.005));

// The explicit weakly-compressible baseline (isphSchemes method wcsph, default sound speed
// 10 sqrt(2 g H') with H' the tank's height, δ-SPH and α = 0.1) on the same tank, 20 particles
// over the depth, for 1 s. It is not exact at rest as the projection is: its pressure follows
// the density, which rings acoustically after the start (the dynamic boundary particles sit
// half a spacing closer than the lattice and push the water off first), so the checks are a
// weakly-compressible code's at this resolution, each with the value measured when the test
// was written: the right wall's force (the function object, every step) averaged over
// 0.25-1 s within 10 % of ρ g H²/2 (+7.3 %; +6.4 % at 40 over the depth), p within 15 % (L2)
// of ρ g depth at 1 s (10.1 %), flow speeds below 5 % of sqrt(g H) (0.9 %), no wall crossing.
TEST(HydrostaticTank, WeaklyCompressibleStaysNearRestForOneSecond) {
  const double rho = 1000, g = 9.81, H = 0.4, dx = 0.02;
  CaseRunner c("hydrostaticTank", "hydrostaticTankWcsph");
  c.set("system/particleMeshDict", "spacing", std::to_string(dx));
  c.set("system/controlDict", "endTime", "1");
  c.set("system/controlDict", "writeInterval", "1");
  c.append("system/isphSchemes", "method wcsph;");
  ASSERT_EQ(c.run(PARTICLEMESH_EXE, "particleMesh"), 0);
  ASSERT_EQ(c.run(SOLVER_EXE, "isphLandslideFoam"), 0) << "see " << c.path() / "log.isphLandslideFoam";
  EXPECT_EQ(c.logValue("isphLandslideFoam", "Wall crossings in the run:"), "0");

  const ParticleCloud cloud = readCloud(c.path() / "1", "particles");
  double maxSpeed = 0, sumError2 = 0, sumExact2 = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != 0) continue;
    maxSpeed = std::max(maxSpeed, cloud.U[i].norm());
    const double exact = rho * g * std::max(H - 0.5 * dx - cloud.positions[i].y(), 0.0);
    sumError2 += (cloud.p[i] - exact) * (cloud.p[i] - exact);
    sumExact2 += exact * exact;
  }
  const double l2 = std::sqrt(sumError2 / sumExact2);

  std::ifstream in(c.path() / "postProcessing/rightWallForce/0/force.dat");
  ASSERT_TRUE(in) << "the function object's force.dat";
  std::string line;
  double sum = 0;
  int n = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    double t = 0, fx = 0;
    row >> t >> fx;
    if (t >= 0.25) sum += std::abs(fx), ++n;
  }
  ASSERT_GT(n, 100);
  const double meanForce = sum / n, exact = 0.5 * rho * g * H * H;
  std::printf("wcsph: L2 error of p %.3g%%, peak speed %.3g m/s, right wall force (mean over 0.25-1 s) %.2f N/m, "
              "exact %.2f (%+.2f%%)\n",
              100 * l2, maxSpeed, meanForce, exact, 100 * (meanForce / exact - 1));
  EXPECT_LT(l2, 0.15) << "L2 error of the pressure against rho g depth";
  EXPECT_LT(maxSpeed, 0.05 * std::sqrt(g * H)) << "peak speed against 0.05 sqrt(g H)";
  EXPECT_NEAR(meanForce / exact, 1.0, 0.10) << "mean right wall force against rho g H^2/2";
}

}  // namespace
