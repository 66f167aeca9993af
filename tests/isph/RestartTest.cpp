// A run stopped and restarted from its last time directory (startFrom latestTime) matches an
// uninterrupted run: the time directory holds the whole state of the solver (positions, U,
// p, origId, and the time step in its time state).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "CaseRunner.hpp"
#include "particles/CloudIO.hpp"

namespace {

using isph::test::CaseRunner;
using namespace isph;

TEST(Restart, StoppedAndRestartedRunMatchesAnUninterruptedOne) {
  const double a = 0.05715, dx = a / 10;
  CaseRunner whole("damBreak", "restartWhole"), split("damBreak", "restartSplit");
  for (CaseRunner* c : {&whole, &split}) {
    c->set("system/particleMeshDict", "spacing", std::to_string(dx));
    c->set("system/controlDict", "writeInterval", "0.02");
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
  std::map<label, std::size_t> indexOf;
  for (std::size_t i = 0; i < B.size(); ++i) indexOf[B.origId[i]] = i;
  double maxDx = 0, maxDu = 0;
  for (std::size_t i = 0; i < A.size(); ++i) {
    const std::size_t j = indexOf.at(A.origId[i]);
    maxDx = std::max(maxDx, (A.positions[i] - B.positions[j]).norm());
    maxDu = std::max(maxDu, (A.U[i] - B.U[j]).norm());
  }
  std::printf("largest difference: position %.3g dx, velocity %.3g m/s\n", maxDx / dx, maxDu);
  // The PPE is solved to 1e-8 (relative): differences of that order, amplified over the
  // 0.02 s after the restart, stay far below a thousandth of a spacing.
  EXPECT_LT(maxDx, 1e-3 * dx);
  EXPECT_LT(maxDu, 1e-3);
}

}  // namespace
