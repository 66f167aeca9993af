// The forces function object in the solver (controlDict `functions`, type patchForces) on the
// right wall of the still-water tank (40 particles over the depth, 0.1 s), against the
// sampleForces utility on the written times: both call setForces on the same particles (the
// solver writes binary fields, exact doubles), so their rows agree to the 8 significant digits
// both print (tolerance 1e-6 relative: a hundred times the print rounding, 5e-8). Both are
// within 2% of ρ g H²/2 per metre. A restart starts a new force.dat under its start time and
// leaves the first one as it was.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "CaseRunner.hpp"

namespace {

using isph::test::CaseRunner;
using isph::test::readText;
namespace fs = std::filesystem;

// The data rows of a force table by time, with the `# Time ...` line that names the columns.
struct ForceFile {
  std::string columns;
  std::map<double, std::vector<double>> rows;
};

ForceFile readForces(const fs::path& file) {
  ForceFile f;
  std::istringstream in(readText(file));
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# Time", 0) == 0) f.columns = line;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    double t = 0;
    row >> t;
    auto& values = f.rows[t];
    for (double v; row >> v;) values.push_back(v);
  }
  return f;
}

TEST(ForcesFunctionObject, AgreesWithSampleForcesAndWithRhoGHSquaredOverTwo) {
  const double rho = 1000, g = 9.81, H = 0.4, exact = 0.5 * rho * g * H * H;
  CaseRunner c("hydrostaticTank", "forcesFunctionObject");
  c.set("system/particleMeshDict", "spacing", "0.01");
  c.set("system/controlDict", "endTime", "0.1");
  c.set("system/controlDict", "writeInterval", "0.05");
  ASSERT_NO_FATAL_FAILURE(c.meshAndSolve());
  EXPECT_NE(c.logValue("isphLandslideFoam", "rightWallForce:"), "") << "the log lists the function object";
  ASSERT_EQ(c.run(SAMPLEFORCES_EXE, "sampleForces"), 0);

  const fs::path inSolverFile = c.path() / "postProcessing/rightWallForce/0/force.dat";
  const ForceFile inSolver = readForces(inSolverFile);
  const ForceFile utility = readForces(c.path() / "postProcessing/sampleForces/0/right.dat");
  EXPECT_EQ(inSolver.columns, utility.columns) << "the same columns and units";
  EXPECT_GE(inSolver.rows.size(), 20u) << "one row per time step";
  int compared = 0;
  for (const auto& [t, values] : utility.rows) {
    if (t == 0) continue;  // the initial particles: before the first step
    const auto it = inSolver.rows.find(t);
    ASSERT_NE(it, inSolver.rows.end()) << "no in-solver row at written time " << t;
    ASSERT_EQ(it->second.size(), values.size());
    for (std::size_t k = 0; k < values.size(); ++k) {
      EXPECT_NEAR(it->second[k], values[k], 1e-6 * std::abs(values[k])) << "column " << k + 2 << " at time " << t;
    }
    const double fn = values[2];  // Fn
    std::printf("time %g: Fn in solver %.8g, sampleForces %.8g N/m, exact %.2f (%+.3f%%)\n", t, it->second[2], fn,
                exact, 100 * (fn / exact - 1));
    EXPECT_NEAR(fn / exact, 1.0, 0.02) << "right wall force against rho g H^2/2 at time " << t;
    EXPECT_NEAR(it->second[2] / exact, 1.0, 0.02);
    ++compared;
  }
  EXPECT_EQ(compared, 2) << "written times 0.05 and 0.1";

  // Restart from 0.1: a new file under postProcessing/rightWallForce/0.1, the first untouched.
  const std::string firstRun = readText(inSolverFile);
  c.set("system/controlDict", "endTime", "0.12");
  ASSERT_EQ(c.run(SOLVER_EXE, "isphLandslideFoam"), 0);
  EXPECT_EQ(readText(inSolverFile), firstRun);
  const ForceFile restarted = readForces(c.path() / "postProcessing/rightWallForce/0.1/force.dat");
  EXPECT_EQ(restarted.columns, inSolver.columns);
  ASSERT_FALSE(restarted.rows.empty());
  EXPECT_GT(restarted.rows.begin()->first, 0.1);
  EXPECT_NEAR(restarted.rows.rbegin()->first, 0.12, 1e-9);
}

}  // namespace
