// A distributed SparseSystem handed to hypre: each rank sets only its own block of rows
// (global column numbers), and the ParCSR matrix holds exactly the serial matrix's rows; the
// hypre solvers then solve the distributed system to the serial solution, with global
// residuals; a block that does not follow the blocks before it is an error on every rank.
#include <gtest/gtest.h>

#include <Eigen/SparseLU>
#include <fmt/format.h>
#include <algorithm>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "linearSolvers/LinearSolver.hpp"
#include "linearSolvers/eigen/EigenMatrix.hpp"
#include "linearSolvers/hypre/HypreSystem.hpp"
#include "parallel/GlobalNumbering.hpp"
#include "parallel/Reduce.hpp"
#include "../linearSolvers/LatticePoisson.hpp"

namespace {

using namespace isph;

// Rows [first, first + n) of the whole system, as one rank assembles them.
SparseSystem block(const SparseSystem& whole, long first, long n) {
  SparseSystem A;
  A.firstRow = first;
  A.symmetricHint = whole.symmetricHint;
  A.rowStart.push_back(0);
  for (long i = first; i < first + n; ++i) {
    for (int k = whole.rowStart[static_cast<std::size_t>(i)]; k < whole.rowStart[static_cast<std::size_t>(i) + 1]; ++k) {
      A.columns.push_back(whole.columns[static_cast<std::size_t>(k)]);
      A.values.push_back(whole.values[static_cast<std::size_t>(k)]);
    }
    A.rowStart.push_back(static_cast<int>(A.columns.size()));
    A.rhs.push_back(whole.rhs[static_cast<std::size_t>(i)]);
  }
  return A;
}

// This rank's share of n rows: as equal as can be, the first ranks one more.
GlobalNumbering shareOf(long n) {
  const long r = thisRank(), p = nRanks();
  return GlobalNumbering::of(n / p + (r < n % p ? 1 : 0));
}

TEST(ParCsrAssembly, EachRanksRowsAreTheSerialMatrixsRows) {
  const SparseSystem whole = test::latticePoisson(30, test::Stencil::Sph21);
  const GlobalNumbering rows = shareOf(whole.nRows());
  const SparseSystem mine = block(whole, rows.first, rows.nLocal);
  checkDistributedSparseSystem(mine);
  const HypreMatrix matrix(mine);
  for (long i = 0; i < rows.nLocal; ++i) {
    const long row = rows.row(i);
    HYPRE_Int size = 0;
    HYPRE_BigInt* columns = nullptr;
    HYPRE_Complex* values = nullptr;
    ASSERT_EQ(HYPRE_ParCSRMatrixGetRow(matrix.parcsr(), static_cast<HYPRE_BigInt>(row), &size, &columns, &values), 0);
    std::vector<std::pair<long, double>> got, want;
    for (HYPRE_Int k = 0; k < size; ++k) got.emplace_back(columns[k], values[k]);
    HYPRE_ParCSRMatrixRestoreRow(matrix.parcsr(), static_cast<HYPRE_BigInt>(row), &size, &columns, &values);
    for (int k = whole.rowStart[static_cast<std::size_t>(row)]; k < whole.rowStart[static_cast<std::size_t>(row) + 1]; ++k) {
      want.emplace_back(whole.columns[static_cast<std::size_t>(k)], whole.values[static_cast<std::size_t>(k)]);
    }
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    ASSERT_EQ(got, want) << "row " << row;
  }
}

TEST(ParCsrAssembly, HypreSolvesTheDistributedSystemToTheSerialSolution) {
  const SparseSystem whole = test::latticePoisson(40, test::Stencil::Sph21);
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  const Eigen::SparseMatrix<double> M = toEigen(whole);
  lu.compute(M);
  ASSERT_EQ(lu.info(), Eigen::Success);
  const Eigen::VectorXd exact = lu.solve(asEigen(whole.rhs));

  const GlobalNumbering rows = shareOf(whole.nRows());
  const SparseSystem mine = block(whole, rows.first, rows.nLocal);
  for (const char* solver : {"PCG", "GMRES", "BiCGSTAB"}) {
    const Dictionary dict =
        Dictionary::parse(fmt::format("p {{ solver {}; tolerance 1e-10; maxIter 500; }}", solver), "isphSolution");
    const auto linear = makeLinearSolver(dict.subDict("p"), "p");
    std::vector<double> x;
    const SolverPerformance perf = linear->solve(mine, x);
    EXPECT_TRUE(perf.converged) << solver << ": " << perf.str();
    EXPECT_LE(perf.finalResidual, 1e-10) << solver;
    // The whole solution, gathered, against the exact one; and its residual by the serial product.
    std::vector<double> all(static_cast<std::size_t>(rows.nGlobal), 0.0);
    std::copy(x.begin(), x.end(), all.begin() + rows.first);
    sumOverRanks(std::span<double>(all));
    EXPECT_LT((asEigen(all) - exact).norm() / exact.norm(), 1e-8) << solver;
    EXPECT_NEAR(normalisedResidual(whole, all), perf.finalResidual, 1e-12) << solver << ": the global residual";
  }
}

TEST(ParCsrAssembly, EigenSolversAreRefusedInAParallelRun) {
  const Dictionary dict = Dictionary::parse("p { solver EigenCG; }", "system/isphSolution");
  if (distributedRun()) {
    EXPECT_THROW(makeLinearSolver(dict.subDict("p"), "p"), FatalError);
  } else {
    EXPECT_NO_THROW(makeLinearSolver(dict.subDict("p"), "p"));
  }
}

TEST(ParCsrAssembly, BlocksThatDoNotFollowOneAnotherAreAnErrorOnEveryRank) {
  const SparseSystem whole = test::latticePoisson(10, test::Stencil::FivePoint);
  const GlobalNumbering rows = shareOf(whole.nRows());
  SparseSystem shifted = block(whole, rows.first, rows.nLocal);
  shifted.firstRow += 1;
  EXPECT_THROW(checkDistributedSparseSystem(shifted), FatalError);
  SparseSystem outside = block(whole, rows.first, rows.nLocal);
  outside.columns.back() = rows.nGlobal;  // one past the last row
  EXPECT_THROW(checkDistributedSparseSystem(outside), FatalError);
}

// A column twice in a row is an error whether it is this rank's row or another's (those are
// checked apart: a row beside the cut between the ranks).
TEST(ParCsrAssembly, AColumnTwiceInARowIsAnErrorOfThisRanksColumnsAndOfAnothers) {
  const SparseSystem whole = test::latticePoisson(10, test::Stencil::FivePoint);
  const GlobalNumbering rows = shareOf(whole.nRows());
  const SparseSystem mine = block(whole, rows.first, rows.nLocal);
  EXPECT_NO_THROW(checkDistributedSparseSystem(mine));
  for (const GlobalIndex twice : {static_cast<GlobalIndex>(rows.first),                  // this rank's
                                  static_cast<GlobalIndex>((rows.first + rows.nLocal) % rows.nGlobal)}) {  // another's, or (one rank) the first
    SparseSystem repeated = mine;
    repeated.columns[0] = twice;
    repeated.columns[1] = twice;
    EXPECT_THROW(checkDistributedSparseSystem(repeated), FatalError) << "column " << twice;
  }
}

}  // namespace
