// The velocity solve's warm start (`U { warmStart }`, ImplicitViscousStep): starting from the
// last step's viscous increment changes only where PCG starts, not what it converges to, so
// the column collapse (the tutorial's own setting, lastIncrement) and the same case started
// from the explicit predictor give the same particles to within what the solvers' tolerance
// allows (the restart and thread-count tests' bound: a thousandth of a spacing, 1 mm/s),
// while the increment, which is what it is for, saves velocity iterations in this slow,
// largely rigid flow (about a fifth over the 2 mm run: doc/notes/velocitySolve.md).
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <string>

#include "CaseRunner.hpp"
#include "particles/CloudIO.hpp"

namespace {

using isph::test::CaseRunner;
using isph::test::largestDifference;
using isph::test::largestMaterialDisplacement;
using namespace isph;

// The PCG iterations of every velocity solve in a solver log.
long velocityIterations(const CaseRunner& c) {
  std::ifstream in(c.path() / "log.isphLandslideFoam");
  const std::regex solve("Solving for U, .*No Iterations ([0-9]+)");
  long sum = 0;
  std::smatch m;
  for (std::string line; std::getline(in, line);) {
    if (std::regex_search(line, m, solve)) sum += std::stol(m[1]);
  }
  return sum;
}

TEST(ImplicitViscousStep, WarmStartFromTheLastIncrementConvergesToTheSameFlowInFewerIterations) {
  const double dx = 0.005;
  const std::string endTime = "0.15";
  CaseRunner increment("columnCollapse", "warmIncrement"), predictor("columnCollapse", "warmPredictor");
  for (CaseRunner* c : {&increment, &predictor}) {
    c->set("system/particleMeshDict", "spacing", std::to_string(dx));
    c->set("system/controlDict", "endTime", endTime);
    c->set("system/controlDict", "writeInterval", endTime);
  }
  predictor.replaceText("system/isphSolution", "warmStart       lastIncrement;", "warmStart       predictor;");
  ASSERT_NO_FATAL_FAILURE(increment.meshAndSolve());
  ASSERT_NO_FATAL_FAILURE(predictor.meshAndSolve());
  EXPECT_EQ(increment.logValue("isphLandslideFoam", "velocity solve warm start:"),
            "the explicit predictor plus the last step's viscous increment");
  EXPECT_EQ(predictor.logValue("isphLandslideFoam", "velocity solve warm start:"), "the explicit predictor u + dt g");

  const ParticleCloud A = readCloud(increment.path() / endTime, "particles");
  const ParticleCloud B = readCloud(predictor.path() / endTime, "particles");
  const ParticleCloud start = readCloud(increment.path() / "0", "particles");
  ASSERT_EQ(A.size(), B.size());
  const auto [maxDx, maxDu] = largestDifference(A, B);
  const long itIncrement = velocityIterations(increment), itPredictor = velocityIterations(predictor);
  std::printf("warm start from the last increment against the predictor: position %.3g dx, velocity %.3g m/s; "
              "velocity iterations %ld against %ld (%.1f%%); the column moved up to %.3g dx\n",
              maxDx / dx, maxDu, itIncrement, itPredictor, 100.0 * (itIncrement - itPredictor) / itPredictor,
              largestMaterialDisplacement(start, A) / dx);
  EXPECT_GT(largestMaterialDisplacement(start, A), 2 * dx) << "the column must flow for the comparison to mean something";
  EXPECT_LT(maxDx, 1e-3 * dx);
  EXPECT_LT(maxDu, 1e-3);
  EXPECT_LT(itIncrement, itPredictor) << "the increment must save iterations in this slow flow";
}

}  // namespace
