// Every solver on manufactured lattice Poisson problems (5-point and SPH-like 21-point):
// agreement with SparseLU, the reported residual, AMG versus unpreconditioned iteration
// counts, warm start, b = 0, non-convergence, and a global numbering offset.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "LatticePoisson.hpp"
#include "SolverTestHelpers.hpp"

namespace isph::test {
namespace {

struct SolverCase {
  const char* label;
  const char* entries;
};

const SolverCase solverCases[] = {
    {"PCG_BoomerAMG", "solver PCG; preconditioner BoomerAMG;"},
    {"GMRES_BoomerAMG", "solver GMRES; preconditioner BoomerAMG;"},
    {"BiCGSTAB_BoomerAMG", "solver BiCGSTAB; preconditioner BoomerAMG;"},
    {"PCG_none", "solver PCG; preconditioner none; maxIter 5000;"},
    {"PCG_diagonal", "solver PCG; preconditioner diagonal; maxIter 5000;"},
    {"EigenBiCGSTAB", "solver EigenBiCGSTAB;"},
    {"EigenCG", "solver EigenCG;"},
};

class EverySolver : public ::testing::TestWithParam<std::tuple<SolverCase, Stencil>> {};

TEST_P(EverySolver, MatchesSparseLUAndReportsItsResidual) {
  const auto& [solverCase, stencil] = GetParam();
  const double tolerance = 1e-8;
  const SparseSystem A = latticePoisson(40, stencil);
  const std::vector<double> exact = exactSolution(A);

  const auto solver = solverFrom(std::string(solverCase.entries) + " tolerance 1e-8; relTol 0;");
  std::vector<double> x;  // zero initial guess
  const SolverPerformance perf = solver->solve(A, x);
  logSolverPerformance(perf);

  EXPECT_TRUE(perf.converged) << perf.str();
  EXPECT_GT(perf.iterations, 0);
  EXPECT_NEAR(perf.initialResidual, 1.0, 1e-12) << "x0 = 0 gives r0 = ||b|| / ||b||";
  EXPECT_LE(perf.finalResidual, tolerance);
  EXPECT_LE(relativeDifference(x, exact), 10 * tolerance) << perf.str();

  // The reported residual is ||b - A x|| / ||b||, recomputed here independently.
  std::vector<double> Ax;
  multiply(A, x, Ax);
  double r2 = 0, b2 = 0;
  for (int i = 0; i < A.nRows(); ++i) {
    r2 += (A.rhs[i] - Ax[i]) * (A.rhs[i] - Ax[i]);
    b2 += A.rhs[i] * A.rhs[i];
  }
  // Only the summation order differs: agreement to rounding of b - A x (~1e-16 ||b|| / ||r||).
  EXPECT_NEAR(perf.finalResidual, std::sqrt(r2 / b2), 1e-6 * perf.finalResidual);
}

INSTANTIATE_TEST_SUITE_P(LatticePoisson, EverySolver,
                         ::testing::Combine(::testing::ValuesIn(solverCases),
                                            ::testing::Values(Stencil::FivePoint, Stencil::Sph21)),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param).label) +
                                  (std::get<1>(info.param) == Stencil::FivePoint ? "_5point"
                                                                                 : "_21point");
                         });

TEST(LinearSolver, BoomerAMGNeedsFarFewerIterationsThanPlainCG) {
  const SparseSystem A = latticePoisson(100, Stencil::FivePoint);
  std::vector<double> xAmg, xPlain;
  const auto amg =
      solverFrom("solver PCG; preconditioner BoomerAMG; tolerance 1e-8;")->solve(A, xAmg);
  const auto plain = solverFrom("solver PCG; preconditioner none; tolerance 1e-8; maxIter 5000;")
                         ->solve(A, xPlain);
  logSolverPerformance(amg);
  logSolverPerformance(plain);
  ASSERT_TRUE(amg.converged) << amg.str();
  ASSERT_TRUE(plain.converged) << plain.str();
  EXPECT_LT(amg.iterations, 30) << amg.str();
  EXPECT_GT(plain.iterations, 100) << plain.str();
  EXPECT_EQ(amg.solverName, "BoomerAMG-PCG");
  EXPECT_EQ(plain.solverName, "PCG");
}

TEST(LinearSolver, AmgIterationsStayRoughlyConstantWithResolution) {
  std::vector<int> iterations;
  for (const int n : {50, 100, 200}) {
    const SparseSystem A = latticePoisson(n, Stencil::Sph21);
    std::vector<double> x;
    const auto perf = solverFrom("solver PCG; tolerance 1e-8;")->solve(A, x);
    logSolverPerformance(perf);
    ASSERT_TRUE(perf.converged) << perf.str();
    iterations.push_back(perf.iterations);
  }
  EXPECT_LE(iterations.back(), 2 * iterations.front() + 2)
      << iterations[0] << " " << iterations[1] << " " << iterations[2];
}

TEST(LinearSolver, WarmStartFromTheSolutionConvergesAtOnce) {
  const SparseSystem A = latticePoisson(40, Stencil::Sph21);
  for (const char* entries : {"solver PCG;", "solver GMRES;", "solver BiCGSTAB;", "solver EigenCG;",
                              "solver EigenBiCGSTAB;", "solver PCG; preconditioner none;"}) {
    std::vector<double> x = exactSolution(A);
    const auto perf = solverFrom(std::string(entries) + " tolerance 1e-8;")->solve(A, x);
    EXPECT_TRUE(perf.converged) << entries;
    EXPECT_LE(perf.iterations, 1) << perf.str();
    EXPECT_LE(perf.initialResidual, 1e-8) << perf.str();
  }
}

TEST(LinearSolver, WarmStartCutsIterations) {
  const SparseSystem A = latticePoisson(60, Stencil::Sph21);
  std::vector<double> x = exactSolution(A);
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] *= 1.0 + 1e-4 * std::sin(0.1 * static_cast<double>(i));
  std::vector<double> cold;
  const auto solver = solverFrom("solver PCG; preconditioner none; tolerance 1e-8; maxIter 5000;");
  const auto warm = solver->solve(A, x);
  const auto coldPerf = solver->solve(A, cold);
  ASSERT_TRUE(warm.converged && coldPerf.converged);
  EXPECT_LT(warm.initialResidual, 1e-2);
  EXPECT_LT(warm.iterations, coldPerf.iterations);
}

TEST(LinearSolver, RelTolStopsRelativeToTheInitialResidual) {
  const SparseSystem A = latticePoisson(40, Stencil::FivePoint);
  std::vector<double> x;
  const auto perf =
      solverFrom("solver PCG; preconditioner none; tolerance 0; relTol 1e-3;")->solve(A, x);
  EXPECT_TRUE(perf.converged) << perf.str();
  EXPECT_LE(perf.finalResidual, 1e-3 * perf.initialResidual);
  EXPECT_GT(perf.finalResidual, 1e-8) << "stops near the relative target, not far below";
}

// solveFinal (the last pass of a nonlinear iteration, OpenFOAM's UFinal) ignores relTol and
// goes on from a relTol solve's result to the tolerance.
TEST(LinearSolver, SolveFinalGoesToTheToleranceWhateverRelTolSays) {
  const SparseSystem A = latticePoisson(40, Stencil::FivePoint);
  const auto solver = solverFrom("solver PCG; preconditioner none; tolerance 1e-9; relTol 1e-2;");
  EXPECT_TRUE(solver->stopsAtRelTol());
  EXPECT_FALSE(solverFrom("solver PCG; relTol 0;")->stopsAtRelTol());
  std::vector<double> x;
  const auto pass = solver->solve(A, x);
  ASSERT_TRUE(pass.converged) << pass.str();
  EXPECT_GT(pass.finalResidual, 1e-6) << "the intermediate pass stops near relTol";
  const auto final = solver->solveFinal(A, x);
  ASSERT_TRUE(final.converged) << final.str();
  EXPECT_LE(final.finalResidual, 1e-9);
  EXPECT_NEAR(final.initialResidual, pass.finalResidual, 1e-3 * pass.finalResidual) << "warm-started from the pass";
}

TEST(LinearSolver, ZeroRightHandSideGivesZeroSolution) {
  SparseSystem A = latticePoisson(20, Stencil::FivePoint);
  std::fill(A.rhs.begin(), A.rhs.end(), 0.0);
  for (const char* entries :
       {"solver PCG;", "solver GMRES;", "solver EigenCG;", "solver EigenLU;"}) {
    std::vector<double> x(A.rhs.size(), 3.0);
    const auto perf = solverFrom(entries)->solve(A, x);
    EXPECT_TRUE(perf.converged) << entries;
    EXPECT_EQ(perf.iterations, 0) << entries;
    EXPECT_EQ(perf.finalResidual, 0.0) << entries;
    for (const double v : x) ASSERT_EQ(v, 0.0) << entries;
  }
}

TEST(LinearSolver, NonConvergenceIsReportedNotThrown) {
  const SparseSystem A = latticePoisson(60, Stencil::Sph21);
  for (const char* entries :
       {"solver PCG; preconditioner none;", "solver GMRES; preconditioner none;",
        "solver BiCGSTAB; preconditioner none;", "solver EigenCG;"}) {
    std::vector<double> x;
    SolverPerformance perf;
    EXPECT_NO_THROW(
        perf = solverFrom(std::string(entries) + " tolerance 1e-10; maxIter 2;")->solve(A, x))
        << entries;
    EXPECT_FALSE(perf.converged) << perf.str();
    EXPECT_LE(perf.iterations, 2) << perf.str();
    EXPECT_GT(perf.finalResidual, 1e-10) << perf.str();
    EXPECT_LT(perf.finalResidual, perf.initialResidual) << perf.str();
  }
}

TEST(LinearSolver, GlobalRowOffsetSolvesTheSame) {
  const SparseSystem A0 = latticePoisson(30, Stencil::Sph21, 0);
  const SparseSystem A1000 = latticePoisson(30, Stencil::Sph21, 1000);
  ASSERT_EQ(A1000.columns.front(), 1000);
  for (const char* entries :
       {"solver PCG;", "solver BiCGSTAB;", "solver EigenBiCGSTAB;", "solver EigenLU;"}) {
    std::vector<double> x0, x1000;
    const auto p0 = solverFrom(std::string(entries) + " tolerance 1e-10;")->solve(A0, x0);
    const auto p1000 = solverFrom(std::string(entries) + " tolerance 1e-10;")->solve(A1000, x1000);
    EXPECT_TRUE(p0.converged && p1000.converged) << p1000.str();
    EXPECT_EQ(p0.iterations, p1000.iterations) << entries;
    EXPECT_LE(relativeDifference(x1000, x0), 1e-12) << entries;
  }
}

TEST(LinearSolver, NonSymmetricSystemWithGmresAndBiCGSTAB) {
  // Convection added to the 5-point stencil (upwind weights 1.5 and 0.5 along x; the row
  // sums are unchanged) makes A non-symmetric.
  SparseSystem A = latticePoisson(40, Stencil::FivePoint);
  A.symmetricHint = false;
  for (int i = 0; i < A.nRows(); ++i) {
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      if (A.columns[k] == i - 1) A.values[k] *= 1.5;
      if (A.columns[k] == i + 1) A.values[k] *= 0.5;
    }
  }
  const std::vector<double> exact = exactSolution(A);
  for (const char* entries : {"solver GMRES;", "solver BiCGSTAB;", "solver EigenBiCGSTAB;"}) {
    std::vector<double> x;
    const auto perf = solverFrom(std::string(entries) + " tolerance 1e-9;")->solve(A, x);
    EXPECT_TRUE(perf.converged) << perf.str();
    EXPECT_LE(relativeDifference(x, exact), 1e-7) << perf.str();
  }
}

TEST(LinearSolver, InitialGuessOfTheWrongSizeIsAnError) {
  const SparseSystem A = latticePoisson(10, Stencil::FivePoint);
  std::vector<double> x(7, 0.0);
  EXPECT_THROW(solverFrom("solver EigenCG;")->solve(A, x), FatalError);
}

}  // namespace
}  // namespace isph::test
