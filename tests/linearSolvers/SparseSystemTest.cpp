// SparseSystem: the CSR checks every solver runs first, mat-vec and the residual.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"
#include "linearSolvers/SparseSystem.hpp"

namespace isph {
namespace {

// [2 -1; -1 2] x = [1 1] on rows 5, 6.
SparseSystem twoByTwo() {
  SparseSystem A;
  A.firstRow = 5;
  A.rowStart = {0, 2, 4};
  A.columns = {5, 6, 6, 5};
  A.values = {2, -1, 2, -1};
  A.rhs = {1, 1};
  return A;
}

TEST(SparseSystem, MultiplyAndResidual) {
  const SparseSystem A = twoByTwo();
  EXPECT_EQ(A.nRows(), 2);
  EXPECT_EQ(A.nNonZeros(), 4);
  std::vector<double> y;
  multiply(A, {1.0, 2.0}, y);
  EXPECT_EQ(y, (std::vector<double>{0.0, 3.0}));
  EXPECT_DOUBLE_EQ(residualNorm(A, {1.0, 1.0}), 0.0);
  EXPECT_DOUBLE_EQ(normalisedResidual(A, {0.0, 0.0}), 1.0);
  EXPECT_DOUBLE_EQ(normalisedResidual(A, {1.0, 2.0}), std::sqrt(1.0 + 4.0) / std::sqrt(2.0));
}

TEST(SparseSystem, ChecksCatchInconsistentArrays) {
  EXPECT_NO_THROW(checkSparseSystem(twoByTwo()));
  SparseSystem A = twoByTwo();
  A.columns[1] = 5;  // column 5 twice in row 5
  EXPECT_THROW(checkSparseSystem(A), FatalError);
  A = twoByTwo();
  A.columns[1] = 7;  // outside rows [5, 7)
  EXPECT_THROW(checkSparseSystem(A), FatalError);
  A = twoByTwo();
  A.rhs.pop_back();
  EXPECT_THROW(checkSparseSystem(A), FatalError);
  A = twoByTwo();
  A.values.pop_back();
  EXPECT_THROW(checkSparseSystem(A), FatalError);
  A = twoByTwo();
  A.rowStart = {0, 3, 2};
  EXPECT_THROW(checkSparseSystem(A), FatalError);
  A = twoByTwo();
  A.rowStart[1] = A.rowStart.back() + 1;  // row 0 past the entries: caught before they are read
  A.rowStart.back() = static_cast<int>(A.values.size());
  EXPECT_THROW(checkSparseSystem(A), FatalError);
  A = twoByTwo();
  A.values[0] = std::nan("");
  EXPECT_THROW(checkSparseSystem(A), FatalError);
  A = twoByTwo();
  A.rowStart.clear();
  EXPECT_THROW(checkSparseSystem(A), FatalError);
}

}  // namespace
}  // namespace isph
