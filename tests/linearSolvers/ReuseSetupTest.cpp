// reuseSetup: a BoomerAMG hierarchy kept across a sequence of slightly changed matrices (as
// the PPE changes from step to step) still preconditions PCG to the same tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "LatticePoisson.hpp"
#include "SolverTestHelpers.hpp"
#include "linearSolvers/hypre/BoomerAMG.hpp"
#include "linearSolvers/hypre/HypreKrylovSolver.hpp"

namespace isph::test {
namespace {

// The matrix with each off-diagonal pair (i, j) scaled by factor(i, j) (symmetric in i and j),
// the diagonal adjusted to stay the row sum of the off-diagonals' magnitude plus the
// Dirichlet part.
template <class Factor>
SparseSystem scaledCouplings(const SparseSystem& base, Factor factor) {
  SparseSystem A = base;
  for (int i = 0; i < A.nRows(); ++i) {
    double change = 0.0;
    int diagonalAt = -1;
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      const long j = A.columns[k] - A.firstRow;
      if (j == i) {
        diagonalAt = k;
        continue;
      }
      const double f = factor(i, j);
      change += A.values[k] * (f - 1.0);
      A.values[k] *= f;
    }
    A.values[diagonalAt] -= change;
  }
  return A;
}

// The lattice matrix with each coupling scaled by 1 + eps * (smooth pattern); step k shifts
// the pattern.
SparseSystem perturbed(const SparseSystem& base, int step, double eps) {
  return scaledCouplings(base, [&](long i, long j) { return 1.0 + eps * std::sin(0.01 * static_cast<double>(i + j) + step); });
}

const HypreKrylovSolver& asHypre(const LinearSolver& s) {
  return dynamic_cast<const HypreKrylovSolver&>(s);
}

TEST(ReuseSetup, PerturbedSequenceConvergesWithOneHierarchy) {
  const SparseSystem base = latticePoisson(80, Stencil::Sph21);
  const auto reuse = solverFrom("solver PCG; tolerance 1e-8; reuseSetup 5;");
  const auto fresh = solverFrom("solver PCG; tolerance 1e-8; reuseSetup 1;");
  std::vector<double> xReuse, xFresh;
  for (int step = 0; step < 5; ++step) {
    const SparseSystem A = perturbed(base, step, 0.05);
    const auto pReuse = reuse->solve(A, xReuse);  // warm-started from the previous step
    const auto pFresh = fresh->solve(A, xFresh);
    ASSERT_TRUE(pReuse.converged) << "step " << step << ": " << pReuse.str();
    ASSERT_TRUE(pFresh.converged) << "step " << step << ": " << pFresh.str();
    EXPECT_LE(pReuse.finalResidual, 1e-8);
    EXPECT_LE(relativeDifference(xReuse, exactSolution(A)), 1e-7) << "step " << step;
    EXPECT_LE(pReuse.iterations, 2 * pFresh.iterations + 5)
        << pReuse.str() << " vs " << pFresh.str();
    EXPECT_EQ(asHypre(*reuse).amg()->lastReused(), step > 0);
  }
  EXPECT_EQ(asHypre(*reuse).amg()->hierarchiesBuilt(), 1);
  EXPECT_EQ(asHypre(*fresh).amg()->hierarchiesBuilt(), 5);
}

TEST(ReuseSetup, HierarchyIsRebuiltAfterNSolvesAndForANewSize) {
  const auto solver = solverFrom("solver PCG; tolerance 1e-8; reuseSetup 2;");
  const auto& amg = *asHypre(*solver).amg();
  const SparseSystem A = latticePoisson(30, Stencil::FivePoint);
  std::vector<double> x;
  for (int i = 0; i < 3; ++i) {
    x.clear();
    ASSERT_TRUE(solver->solve(A, x).converged);
  }
  EXPECT_EQ(amg.hierarchiesBuilt(), 2);  // solves 1-2 share one, solve 3 builds the next
  const SparseSystem B = latticePoisson(31, Stencil::FivePoint);
  x.clear();
  const auto perf = solver->solve(B, x);
  EXPECT_TRUE(perf.converged) << perf.str();
  EXPECT_EQ(amg.hierarchiesBuilt(), 3);  // another size: rebuilt although one reuse was left
  EXPECT_FALSE(amg.lastReused());
}

// keepPreconditionerForNextSolve: the hierarchy is kept for the one solve that follows the
// hint (a fixed-point pass on a slightly changed matrix), whatever reuseSetup says, and the
// solve after it builds afresh.
TEST(ReuseSetup, KeepHintReusesForTheNextSolveOnly) {
  const SparseSystem base = latticePoisson(60, Stencil::Sph21);
  const auto solver = solverFrom("solver PCG; tolerance 1e-8; reuseSetup 1;");
  const auto& amg = *asHypre(*solver).amg();
  std::vector<double> x;
  ASSERT_TRUE(solver->solve(perturbed(base, 0, 0.05), x).converged);
  solver->keepPreconditionerForNextSolve();
  const SparseSystem A1 = perturbed(base, 1, 0.05);
  const auto kept = solver->solve(A1, x);
  ASSERT_TRUE(kept.converged) << kept.str();
  EXPECT_TRUE(amg.lastReused());
  EXPECT_EQ(amg.hierarchiesBuilt(), 1);
  EXPECT_LE(relativeDifference(x, exactSolution(A1)), 1e-7);
  ASSERT_TRUE(solver->solve(perturbed(base, 2, 0.05), x).converged);
  EXPECT_FALSE(amg.lastReused());
  EXPECT_EQ(amg.hierarchiesBuilt(), 2);
}

// A matrix of another size is never solved with a kept hierarchy.
TEST(ReuseSetup, KeepHintIsIgnoredForANewSize) {
  const auto solver = solverFrom("solver PCG; tolerance 1e-8; reuseSetup 1;");
  std::vector<double> x;
  ASSERT_TRUE(solver->solve(latticePoisson(30, Stencil::FivePoint), x).converged);
  solver->keepPreconditionerForNextSolve();
  x.clear();
  const auto perf = solver->solve(latticePoisson(31, Stencil::FivePoint), x);
  EXPECT_TRUE(perf.converged) << perf.str();
  EXPECT_FALSE(asHypre(*solver).amg()->lastReused());
  EXPECT_EQ(asHypre(*solver).amg()->hierarchiesBuilt(), 2);
}

// P A Pᵀ for the permutation that reverses the order of the unknowns in blocks of 7 (as the
// reordering of the particles renumbers them).
SparseSystem renumbered(const SparseSystem& A) {
  const int n = A.nRows();
  std::vector<long> newOf(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) newOf[static_cast<std::size_t>(i)] = (i % 7) * ((n + 6) / 7) + i / 7;
  std::vector<long> sorted(newOf);
  std::sort(sorted.begin(), sorted.end());
  for (auto& v : newOf) v = std::lower_bound(sorted.begin(), sorted.end(), v) - sorted.begin();  // dense 0..n-1
  std::vector<int> oldOf(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) oldOf[static_cast<std::size_t>(newOf[static_cast<std::size_t>(i)])] = i;
  SparseSystem B;
  B.firstRow = 0;
  B.symmetricHint = A.symmetricHint;
  B.rowStart.assign(1, 0);
  for (int r = 0; r < n; ++r) {
    const int i = oldOf[static_cast<std::size_t>(r)];
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      B.columns.push_back(newOf[static_cast<std::size_t>(A.columns[k] - A.firstRow)]);
      B.values.push_back(A.values[k]);
    }
    B.rowStart.push_back(static_cast<int>(B.columns.size()));
    B.rhs.push_back(A.rhs[static_cast<std::size_t>(i)]);
  }
  return B;
}

// rebuildPreconditionerForNextSolve (the particles were reordered): the next solve builds a
// hierarchy for the new numbering although reuses were left, and converges as a fresh one.
TEST(ReuseSetup, RebuildHintBuildsAfreshForRenumberedUnknowns) {
  const SparseSystem A = latticePoisson(60, Stencil::Sph21);
  const SparseSystem B = renumbered(A);
  const auto solver = solverFrom("solver PCG; tolerance 1e-8; reuseSetup 10;");
  const auto fresh = solverFrom("solver PCG; tolerance 1e-8;");
  const auto& amg = *asHypre(*solver).amg();
  std::vector<double> x, xFresh;
  ASSERT_TRUE(solver->solve(A, x).converged);
  solver->rebuildPreconditionerForNextSolve();
  x.clear();
  const auto perf = solver->solve(B, x);
  const auto perfFresh = fresh->solve(B, xFresh);
  ASSERT_TRUE(perf.converged) << perf.str();
  EXPECT_FALSE(amg.lastReused());
  EXPECT_EQ(amg.hierarchiesBuilt(), 2);
  EXPECT_LE(perf.iterations, perfFresh.iterations + 1) << perf.str() << " vs " << perfFresh.str();
  EXPECT_LE(relativeDifference(x, exactSolution(B)), 1e-7);
  x.clear();
  ASSERT_TRUE(solver->solve(B, x).converged);  // and reuses again after it
  EXPECT_TRUE(amg.lastReused());
}

// A kept hierarchy that has become a poor preconditioner is rebuilt before reuseSetup runs
// out: here the couplings of half the domain fall by three decades (a soil that starts to
// yield), the next solve with the old hierarchy takes far more iterations than its first, and
// the solve after that builds afresh.
TEST(ReuseSetup, DriftedMatrixGetsAFreshHierarchy) {
  const SparseSystem A = latticePoisson(60, Stencil::Sph21);
  const long half = A.nRows() / 2;  // the couplings of the first half of the rows × 1e-3
  const SparseSystem B = scaledCouplings(A, [&](long i, long j) { return i < half || j < half ? 1e-3 : 1.0; });
  const auto solver = solverFrom("solver PCG; tolerance 1e-8; reuseSetup 100;");
  const auto& amg = *asHypre(*solver).amg();
  std::vector<double> x;
  const auto first = solver->solve(A, x);
  ASSERT_TRUE(first.converged) << first.str();
  x.clear();
  const auto stale = solver->solve(B, x);  // the old hierarchy
  ASSERT_TRUE(stale.converged) << stale.str();
  EXPECT_TRUE(amg.lastReused());
  EXPECT_GT(2 * stale.iterations, 3 * first.iterations + 4) << stale.str() << " vs " << first.str();
  x.clear();
  const auto rebuilt = solver->solve(B, x);
  ASSERT_TRUE(rebuilt.converged) << rebuilt.str();
  EXPECT_FALSE(amg.lastReused());
  EXPECT_EQ(amg.hierarchiesBuilt(), 2);
  EXPECT_LT(rebuilt.iterations, stale.iterations) << rebuilt.str() << " vs " << stale.str();
}

// With reuseSetup > 1 the smoother defaults to Gauss-Seidel, which works on the current
// matrix (the l1 smoothers' row norms are the set-up's; BoomerAMG.hpp).
TEST(ReuseSetup, SmootherDefaultsToGaussSeidelWhenReusing) {
  const auto parse = [](const std::string& entries) {
    const Dictionary d = Dictionary::parse("U\n{\n" + entries + "\n}\n", "system/isphSolution");
    return BoomerAMGControls::read(d.subDict("U"));
  };
  EXPECT_EQ(parse("reuseSetup 1;").relaxType, -1);  // hypre's default, l1 Gauss-Seidel
  EXPECT_EQ(parse("reuseSetup 5;").relaxType, 3);
  EXPECT_EQ(parse("reuseSetup 5;\nsmoother symmetricGaussSeidel;").relaxType, 6);
  testing::internal::CaptureStderr();
  EXPECT_EQ(parse("reuseSetup 5;\nsmoother l1GaussSeidel;").relaxType, -1);
  const std::string warned = testing::internal::GetCapturedStderr();
  EXPECT_NE(warned.find("system/isphSolution"), std::string::npos) << warned;
  EXPECT_NE(warned.find("GaussSeidel or symmetricGaussSeidel"), std::string::npos) << warned;
}

TEST(ReuseSetup, ReuseWorksWithGmresAndBiCGSTAB) {
  const SparseSystem base = latticePoisson(40, Stencil::Sph21);
  for (const char* entries : {"solver GMRES; reuseSetup 3;", "solver BiCGSTAB; reuseSetup 3;"}) {
    const auto solver = solverFrom(std::string(entries) + " tolerance 1e-9;");
    std::vector<double> x;
    for (int step = 0; step < 3; ++step) {
      const SparseSystem A = perturbed(base, step, 0.05);
      const auto perf = solver->solve(A, x);
      EXPECT_TRUE(perf.converged) << entries << " step " << step << ": " << perf.str();
    }
    EXPECT_EQ(asHypre(*solver).amg()->hierarchiesBuilt(), 1) << entries;
  }
}

}  // namespace
}  // namespace isph::test
