// The same case on one and on two OpenMP threads gives the same particles (issue 9: "the same
// results for 1 and 2 threads within solver tolerance"). Every particle loop writes only its
// own particle's data and the reductions are maxima, so the sums are taken in the same order
// whatever the thread count; the PPE (hypre, without OpenMP in Debian) is serial. The
// tolerance is that of the PPE's, as in the restart test: a thousandth of a spacing. Both
// methods: the projection with the semi-implicit granular step (the column collapse, which
// runs every phase: rheology, viscous solve, friction, PPE, shifting) and the
// weakly-compressible step (the dam break).
#include <gtest/gtest.h>

#include <string>

#include "CaseRunner.hpp"
#include "particles/CloudIO.hpp"

namespace {

using isph::test::CaseRunner;
using isph::test::largestDifference;
using isph::test::largestMaterialDisplacement;
using namespace isph;

void checkThreadCounts(const std::string& tutorial, const std::string& name, double dx, const std::string& endTime,
                       const std::string& schemesEntry) {
  CaseRunner one(tutorial, name + "One"), two(tutorial, name + "Two");
  for (CaseRunner* c : {&one, &two}) {
    c->set("system/particleMeshDict", "spacing", std::to_string(dx));
    c->set("system/controlDict", "endTime", endTime);
    c->set("system/controlDict", "writeInterval", endTime);
    if (!schemesEntry.empty()) c->append("system/isphSchemes", schemesEntry);
    ASSERT_EQ(c->run(PARTICLEMESH_EXE, "particleMesh"), 0);
  }
  ASSERT_EQ(one.run(SOLVER_EXE, "isphLandslideFoam", "", "OMP_NUM_THREADS=1"), 0);
  ASSERT_EQ(two.run(SOLVER_EXE, "isphLandslideFoam", "", "OMP_NUM_THREADS=2"), 0);
  EXPECT_EQ(two.logValue("isphLandslideFoam", "nThreads :").substr(0, 2), "2 ") << "the banner of the two-thread run";

  const ParticleCloud A = readCloud(one.path() / endTime, "particles");
  const ParticleCloud B = readCloud(two.path() / endTime, "particles");
  ASSERT_EQ(A.size(), B.size());
  const auto [maxDx, maxDu] = largestDifference(A, B);
  const double moved = largestMaterialDisplacement(readCloud(one.path() / "0", "particles"), A);
  std::printf("%s: 1 against 2 threads: position %.3g dx, velocity %.3g m/s (the material moved up to %.3g dx)\n",
              name.c_str(), maxDx / dx, maxDu, moved / dx);
  EXPECT_GT(moved, 2 * dx) << "the case must move for the comparison to mean something";
  EXPECT_LT(maxDx, 1e-3 * dx);
  EXPECT_LT(maxDu, 1e-3);
}

TEST(ThreadCount, GranularCollapseIsTheSameOnOneAndTwoThreads) {
  checkThreadCounts("columnCollapse", "threadsColumn", 0.005, "0.1", "");
}

TEST(ThreadCount, WeaklyCompressibleDamBreakIsTheSameOnOneAndTwoThreads) {
  checkThreadCounts("damBreak", "threadsWcsph", 0.05715 / 10, "0.06", "method wcsph;");
}

}  // namespace
