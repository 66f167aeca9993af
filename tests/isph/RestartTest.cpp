// A run stopped and restarted from its last time directory (startFrom latestTime) matches an
// uninterrupted run: the time directory holds the whole state of the solver (positions, U,
// p, origId, and the time step in its time state; with method wcsph also the densities).
#include <gtest/gtest.h>

#include <cmath>

#include "CaseRunner.hpp"
#include "particles/CloudIO.hpp"

namespace {

using isph::test::CaseRunner;
using isph::test::largestDifference;
using namespace isph;

void checkRestart(const std::string& name, const std::string& schemesEntry) {
  const double a = 0.05715, dx = a / 10;
  CaseRunner whole("damBreak", name + "Whole"), split("damBreak", name + "Split");
  for (CaseRunner* c : {&whole, &split}) {
    c->set("system/particleMeshDict", "spacing", std::to_string(dx));
    c->set("system/controlDict", "writeInterval", "0.02");
    if (!schemesEntry.empty()) c->append("system/isphSchemes", schemesEntry);
    ASSERT_EQ(c->run(PARTICLEMESH_EXE, "particleMesh"), 0);
  }
  whole.set("system/controlDict", "endTime", "0.06");
  ASSERT_EQ(whole.run(SOLVER_EXE, "isphLandslideFoam"), 0);
  split.set("system/controlDict", "endTime", "0.04");
  ASSERT_EQ(split.run(SOLVER_EXE, "isphLandslideFoam"), 0);
  split.set("system/controlDict", "endTime", "0.06");
  ASSERT_EQ(split.run(SOLVER_EXE, "isphLandslideFoam.restart"), 0);

  const ParticleCloud A = readCloud(whole.path() / "0.06", "particles");
  const ParticleCloud B = readCloud(split.path() / "0.06", "particles");
  ASSERT_EQ(A.size(), B.size());
  const auto [maxDx, maxDu] = largestDifference(A, B);
  std::printf("largest difference: position %.3g dx, velocity %.3g m/s\n", maxDx / dx, maxDu);
  // The PPE is solved to 1e-8 (relative): differences of that order, amplified over the
  // 0.02 s after the restart, stay far below a thousandth of a spacing. (The explicit method
  // has no solve: its differences are round-off from the reordering of the sums.)
  EXPECT_LT(maxDx, 1e-3 * dx);
  EXPECT_LT(maxDu, 1e-3);
}

TEST(Restart, StoppedAndRestartedRunMatchesAnUninterruptedOne) { checkRestart("restart", ""); }

// The weakly-compressible state includes the densities (of the walls' dynamic boundary
// particles too): without them a restart would start the walls from the extrapolated wall
// pressure and the water from its cut-off p.
TEST(Restart, WeaklyCompressibleRunRestartsFromItsDensities) { checkRestart("restartWcsph", "method wcsph;"); }

}  // namespace
