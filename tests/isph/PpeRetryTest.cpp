// A PPE that does not converge within maxIter is retried once with half the step; if the
// retry fails too, the run stops (non-zero exit) with a message that names the solve, both
// attempts' times, steps and residuals, and the last written time directory stays intact.
// Still-water tank at 20 particles over the depth.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "CaseRunner.hpp"
#include "core/time/TimeName.hpp"
#include "particles/CloudIO.hpp"

namespace {

using isph::test::CaseRunner;
using isph::test::readText;
namespace fs = std::filesystem;

TEST(PpeRetry, SecondFailureStopsWithAMessageAndKeepsTheLastTime) {
  CaseRunner c("hydrostaticTank", "ppeRetry");
  c.set("system/particleMeshDict", "spacing", "0.02");
  c.set("system/controlDict", "endTime", "0.02");
  c.set("system/controlDict", "writeInterval", "0.02");
  ASSERT_NO_FATAL_FAILURE(c.meshAndSolve());
  const std::string written = readText(c.path() / "0.02/lagrangian/particles/p");
  ASSERT_FALSE(written.empty());

  // One GMRES iteration cannot reach 1e-14: both attempts fail.
  c.set("system/controlDict", "endTime", "0.04");
  std::ofstream(c.path() / "system/isphSolution")
      << "p { solver GMRES; preconditioner BoomerAMG; tolerance 1e-14; relTol 0; maxIter 1; }\n";
  EXPECT_NE(c.run(SOLVER_EXE, "isphLandslideFoam"), 0);
  const std::string log = readText(c.path() / "log.isphLandslideFoam");
  EXPECT_NE(log.find("retrying the step once with half the step"), std::string::npos) << log;
  EXPECT_NE(log.find("did not converge, after one retry with a smaller step"), std::string::npos) << log;
  EXPECT_NE(log.find("first attempt: time 0.02"), std::string::npos) << "when: the time of each attempt\n" << log;
  EXPECT_NE(log.find("retry:         time 0.02"), std::string::npos) << log;
  EXPECT_NE(log.find("system/isphSolution"), std::string::npos) << "where to act\n" << log;

  // Nothing written after the failure; 0.02 as it was and readable.
  std::string times;
  for (const auto& t : isph::listTimes(c.path())) times += t.name + " ";
  EXPECT_EQ(times, "0 0.02 ");
  EXPECT_EQ(readText(c.path() / "0.02/lagrangian/particles/p"), written);
  EXPECT_NO_THROW(isph::readCloud(c.path() / "0.02", "particles"));
}

}  // namespace
