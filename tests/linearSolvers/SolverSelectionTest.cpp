// Run-time selection from system/isphSolution: names, defaults, errors that name the file
// and line and list the valid choices, unknown keywords, and the log line.
#include <gtest/gtest.h>

#include "SolverTestHelpers.hpp"
#include "core/Error.hpp"

namespace isph::test {
namespace {

FatalError errorOf(const std::string& entries) {
  try {
    solverFrom(entries);
  } catch (const FatalError& e) {
    return e;
  }
  ADD_FAILURE() << "no FatalError for: " << entries;
  return FatalError("none");
}

void expectMentions(const std::string& text, const std::vector<std::string>& words) {
  for (const auto& w : words)
    EXPECT_NE(text.find(w), std::string::npos) << "'" << w << "' missing in:\n" << text;
}

TEST(SolverSelection, EveryNameIsRegistered) {
  const std::vector<std::string> expected = {"BiCGSTAB", "EigenBiCGSTAB", "EigenCG",
                                             "EigenLU",  "GMRES",         "PCG"};
  EXPECT_EQ(linearSolverNames(), expected);
}

TEST(SolverSelection, NamesInTheLog) {
  EXPECT_EQ(solverFrom("solver PCG;")->name(), "BoomerAMG-PCG");
  EXPECT_EQ(solverFrom("solver GMRES; preconditioner diagonal;")->name(), "diagonal-GMRES");
  EXPECT_EQ(solverFrom("solver BiCGSTAB; preconditioner none;")->name(), "BiCGSTAB");
  EXPECT_EQ(solverFrom("solver EigenBiCGSTAB;")->name(), "Eigen-BiCGSTAB");
  EXPECT_EQ(solverFrom("solver EigenCG;")->name(), "Eigen-CG");
  EXPECT_EQ(solverFrom("solver EigenLU;")->name(), "Eigen-LU");
}

TEST(SolverSelection, DefaultsToBoomerAMGPreconditionedCG) {
  EXPECT_EQ(solverFrom("")->name(), "BoomerAMG-PCG");
  const auto c = LinearSolverControls::read(Dictionary(), "p");
  EXPECT_EQ(c.tolerance, 1e-6);
  EXPECT_EQ(c.relTol, 0.0);
  EXPECT_EQ(c.maxIter, 1000);
}

TEST(SolverSelection, UnknownSolverNamesFileLineAndChoices) {
  const FatalError e = errorOf("tolerance 1e-8;\nsolver PCGG;");
  ASSERT_TRUE(e.where().known()) << e.report();
  EXPECT_EQ(*e.where().file, "system/isphSolution");
  EXPECT_EQ(e.where().line, 4);
  expectMentions(e.report(),
                 {"PCGG", "PCG", "GMRES", "BiCGSTAB", "EigenCG", "EigenBiCGSTAB", "EigenLU"});
}

TEST(SolverSelection, UnknownPreconditionerNamesFileLineAndChoices) {
  const FatalError e = errorOf("solver GMRES;\npreconditioner ILU;");
  ASSERT_TRUE(e.where().known()) << e.report();
  EXPECT_EQ(*e.where().file, "system/isphSolution");
  EXPECT_EQ(e.where().line, 4);
  expectMentions(e.report(), {"ILU", "BoomerAMG", "diagonal", "none"});
}

TEST(SolverSelection, UnknownAmgChoicesAndBadValues) {
  expectMentions(errorOf("solver PCG; coarsenType Ruge;").report(),
                 {"Ruge", "HMIS", "PMIS", "Falgout"});
  expectMentions(errorOf("solver PCG; interpType linear;").report(),
                 {"linear", "extPI", "classical"});
  expectMentions(errorOf("solver PCG; smoother Jacobi;").report(), {"l1GaussSeidel", "l1Jacobi"});
  expectMentions(errorOf("solver PCG; strongThreshold 1.5;").report(), {"strongThreshold"});
  expectMentions(errorOf("solver PCG; reuseSetup 0;").report(), {"reuseSetup"});
  expectMentions(errorOf("solver PCG; tolerance -1;").report(), {"tolerance"});
  expectMentions(errorOf("solver PCG; relTol 1;").report(), {"relTol"});
  expectMentions(errorOf("solver EigenCG; maxIter 0;").report(), {"maxIter"});
  expectMentions(errorOf("solver GMRES; kDim 0;").report(), {"kDim"});
}

TEST(SolverSelection, EveryAmgSettingIsAccepted) {
  const int before = warningCount();
  solverFrom(
      "solver PCG; preconditioner BoomerAMG; strongThreshold 0.5; coarsenType PMIS; interpType ext;"
      " pMaxElmts 6; aggNumLevels 1; smoother symmetricGaussSeidel; reuseSetup 3;");
  solverFrom("solver PCG; smoother l1Jacobi;");  // an l1 smoother without reuse (BoomerAMG.hpp)
  EXPECT_EQ(warningCount(), before);
}

// An entry the solver does not use warns; a misspelt one (it would leave the default tolerance
// in force) is an error.
TEST(SolverSelection, UnusedKeywordsAreWarnedAboutMisspeltOnesRefused) {
  const int before = warningCount();
  solverFrom("solver EigenCG; preconditioner BoomerAMG;");  // Eigen's CG has its own
  EXPECT_EQ(warningCount(), before + 1);
  const std::string report = errorOf("solver PCG; tolerence 1e-8;").report();
  EXPECT_NE(report.find("did you mean tolerance?"), std::string::npos) << report;
}

TEST(SolverSelection, PerformanceLineInOpenFOAMForm) {
  const SolverPerformance perf{.solverName = "BoomerAMG-PCG",
                               .field = "p",
                               .initialResidual = 1e-2,
                               .finalResidual = 3.2e-9,
                               .iterations = 7};
  EXPECT_EQ(perf.str(),
            "BoomerAMG-PCG:  Solving for p, Initial residual = 0.01, Final residual = 3.2e-09, No "
            "Iterations 7");
}

TEST(SolverSelection, NotConvergedIsLoggedAsAWarning) {
  SolverPerformance perf{.solverName = "PCG", .field = "p", .converged = false};
  const int before = warningCount();
  logSolverPerformance(perf);
  EXPECT_EQ(warningCount(), before + 1);
  perf.converged = true;
  logSolverPerformance(perf);
  EXPECT_EQ(warningCount(), before + 1);
}

}  // namespace
}  // namespace isph::test
