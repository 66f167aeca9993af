// The solver class is chosen by isphSchemes' `method`, by name (ParticleSolver::New): the
// projection (ProjectionSolver) by default and for `isph`, the weakly-compressible baseline
// (WeaklyCompressibleSolver) for `wcsph`, each stepping as its method does; an unknown name is
// an error with the file, the line, the choices and a "did you mean". On the still-water tank
// at a coarse 4 cm spacing (particleMesh run on a copy of the tutorial), in this process.
#include <gtest/gtest.h>

#include <fstream>
#include <optional>
#include <string>

#include "../CaseRunner.hpp"
#include "core/Error.hpp"
#include "core/time/Time.hpp"
#include "isph/solvers/ProjectionSolver.hpp"
#include "isph/solvers/WeaklyCompressibleSolver.hpp"

namespace isph {
namespace {

using test::CaseRunner;

// The tank's case with `method` in system/isphSchemes (none: the entry left out), its
// particles made.
void makeTank(CaseRunner& c, const std::optional<std::string>& method) {
  c.set("system/particleMeshDict", "spacing", "0.04");
  if (method) {
    std::ofstream(c.path() / "system/isphSchemes", std::ios::app) << "\nmethod " << *method << ";\n";
  }
  ASSERT_EQ(c.run(PARTICLEMESH_EXE, "particleMesh"), 0) << "see " << c.path() / "log.particleMesh";
}

// Two steps of the solver at its own time step.
std::vector<StepReport> twoSteps(Time& time, ParticleSolver& solver) {
  std::vector<StepReport> reports;
  for (int i = 0; i < 2; ++i) {
    time.adjustDeltaT(solver.nextDeltaT(time).value());
    ++time;
    reports.push_back(solver.step(time));
  }
  return reports;
}

TEST(ParticleSolver, WithoutAMethodEntryRunsTheProjection) {
  CaseRunner c("hydrostaticTank", "solverDefault");
  ASSERT_NO_FATAL_FAILURE(makeTank(c, std::nullopt));
  Time time(c.path());
  const auto solver = ParticleSolver::New(time);
  EXPECT_NE(dynamic_cast<ProjectionSolver*>(solver.get()), nullptr);
}

TEST(ParticleSolver, MethodIsphStepsByTheProjection) {
  CaseRunner c("hydrostaticTank", "solverIsph");
  ASSERT_NO_FATAL_FAILURE(makeTank(c, "isph"));
  Time time(c.path());
  const auto solver = ParticleSolver::New(time);
  ASSERT_NE(dynamic_cast<ProjectionSolver*>(solver.get()), nullptr);
  // Water at rest: no flow speed and no sound speed, so no Courant limit.
  EXPECT_EQ(solver->nextDeltaT(time).courant, 1e300);
  for (const StepReport& r : twoSteps(time, *solver)) {
    EXPECT_EQ(r.ppe.field, "p") << "each step solves the PPE";
    EXPECT_TRUE(r.ppe.converged);
    EXPECT_EQ(r.densityVariation, -1) << "the projection has no density variation";
  }
}

TEST(ParticleSolver, MethodWcsphStepsByTheWeaklyCompressibleBaseline) {
  CaseRunner c("hydrostaticTank", "solverWcsph");
  ASSERT_NO_FATAL_FAILURE(makeTank(c, "wcsph"));
  Time time(c.path());
  const auto solver = ParticleSolver::New(time);
  ASSERT_NE(dynamic_cast<WeaklyCompressibleSolver*>(solver.get()), nullptr);
  // Water at rest: the acoustic Courant limit alone, maxCo h / c0.
  const TimeStepLimits limits = solver->nextDeltaT(time);
  EXPECT_LT(limits.courant, 1e-3);
  EXPECT_EQ(limits.limiting(), "Courant");
  for (const StepReport& r : twoSteps(time, *solver)) {
    EXPECT_TRUE(r.ppe.field.empty()) << "no PPE";
    EXPECT_GE(r.densityVariation, 0);
    EXPECT_LT(r.densityVariation, 0.01) << "weakly compressible: the tank within 1 % of its density";
  }
}

TEST(ParticleSolver, AnUnknownMethodIsAnErrorAtItsLineWithTheChoices) {
  CaseRunner c("hydrostaticTank", "solverUnknown");
  ASSERT_NO_FATAL_FAILURE(makeTank(c, "wcsp"));
  Time time(c.path());
  try {
    ParticleSolver::New(time);
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string what = e.report();
    EXPECT_NE(what.find("isphSchemes, line"), std::string::npos) << what;
    EXPECT_NE(what.find("unknown method 'wcsp'"), std::string::npos) << what;
    EXPECT_NE(what.find("isph, wcsph"), std::string::npos) << what;
    EXPECT_NE(what.find("did you mean wcsph?"), std::string::npos) << what;
  }
}

// An old case that still names a variant removed with issue 48 (here `incrementalPressure
// granular;`, as slidingBlock had it) is refused by the solver at the entry's line, in a
// granular scene and in a fluid one alike: it would otherwise run a step other than the one
// its dictionary names.
TEST(ParticleSolver, ARemovedProjectionVariantIsAnErrorAtItsLine) {
  for (const char* tutorial : {"granularAtRest", "hydrostaticTank"}) {
    SCOPED_TRACE(tutorial);
    CaseRunner c(tutorial, std::string("solverRemovedVariant_") + tutorial);
    c.set("system/particleMeshDict", "spacing", "0.04");
    std::ofstream(c.path() / "system/isphSchemes", std::ios::app) << "\nincrementalPressure granular;\n";
    ASSERT_EQ(c.run(PARTICLEMESH_EXE, "particleMesh"), 0) << "see " << c.path() / "log.particleMesh";
    Time time(c.path());
    try {
      ParticleSolver::New(time);
      FAIL() << "expected a FatalError";
    } catch (const FatalError& e) {
      EXPECT_NE(e.report().find("keyword 'incrementalPressure'"), std::string::npos) << e.report();
      EXPECT_NE(e.report().find("was removed"), std::string::npos) << e.report();
      EXPECT_NE(e.report().find("isphSchemes, line"), std::string::npos) << e.report();
    }
  }
}

}  // namespace
}  // namespace isph
