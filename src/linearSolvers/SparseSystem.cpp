#include "linearSolvers/SparseSystem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "parallel/GlobalNumbering.hpp"

namespace isph {

namespace {

// The sizes of the arrays (O(1)).
void checkSizes(const SparseSystem& A) {
  const int n = A.nRows();
  if (A.rowStart.empty() || A.rowStart.front() != 0) {
    fatalError("sparse system: rowStart must have nRows + 1 entries and start at 0");
  }
  const auto nnz = static_cast<std::size_t>(A.rowStart.back());
  if (A.columns.size() != nnz || A.values.size() != nnz) {
    fatalError(
        fmt::format("sparse system: rowStart ends at {} but there are {} columns and {} values",
                    nnz, A.columns.size(), A.values.size()));
  }
  if (A.rhs.size() != static_cast<std::size_t>(n)) {
    fatalError(fmt::format("sparse system: {} rows but the right-hand side has {} entries", n,
                           A.rhs.size()));
  }
}

void checkRowStart(const SparseSystem& A, int i) {
  if (A.rowStart[i + 1] < A.rowStart[i]) {
    fatalError(fmt::format("sparse system: rowStart decreases at row {}", A.firstRow + i));
  }
  if (A.rowStart[i + 1] > A.rowStart.back()) {  // (before its entries are read)
    fatalError(fmt::format("sparse system: row {} ends at entry {}, past the last ({})", A.firstRow + i,
                           A.rowStart[i + 1], A.rowStart.back()));
  }
}

void checkFinite(const SparseSystem& A, int i, int k) {
  if (!std::isfinite(A.values[k])) {
    fatalError(fmt::format("sparse system: A({}, {}) = {} is not finite", A.firstRow + i,
                           A.columns[k], A.values[k]));
  }
}

void checkFiniteRhs(const SparseSystem& A, int i) {
  if (!std::isfinite(A.rhs[i])) {
    fatalError(fmt::format("sparse system: b({}) = {} is not finite", A.firstRow + i, A.rhs[i]));
  }
}

// The checks that do not depend on where the columns lie: sizes, rowStart, finite values.
void checkShape(const SparseSystem& A) {
  checkSizes(A);
  for (int i = 0; i < A.nRows(); ++i) {
    checkRowStart(A, i);
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) checkFinite(A, i, k);
    checkFiniteRhs(A, i);
  }
}

}  // namespace

// One pass over the entries (the shape's checks with the columns'): it runs before every solve,
// a stick/slip pass's too (the two passes it took were 2 % of the barrier's time loop).
void checkSparseSystem(const SparseSystem& A) {
  checkSizes(A);
  const int n = A.nRows();
  // lastSeen[c] == i marks column c as used in row i: repeated columns are caught in O(nnz).
  std::vector<int> lastSeen(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i) {
    checkRowStart(A, i);
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      checkFinite(A, i, k);
      const long c = A.columns[k] - A.firstRow;
      if (c < 0 || c >= n) {
        fatalError(fmt::format(
            "sparse system: row {} has column {} outside the rows [{}, {}) of this rank",
            A.firstRow + i, A.columns[k], A.firstRow, A.firstRow + n));
      }
      if (lastSeen[c] == i) {
        fatalError(
            fmt::format("sparse system: row {} has column {} twice", A.firstRow + i, A.columns[k]));
      }
      lastSeen[c] = i;
    }
    checkFiniteRhs(A, i);
  }
}

void checkDistributedSparseSystem(const SparseSystem& A) {
  checkShape(A);
  const GlobalNumbering rows = GlobalNumbering::of(A.nRows());
  if (A.firstRow != rows.first) {
    fatalError(fmt::format("distributed sparse system: this rank's rows start at {}, but the ranks before it "
                           "hold {} rows",
                           A.firstRow, rows.first));
  }
  std::vector<GlobalIndex> columns;
  for (int i = 0; i < A.nRows(); ++i) {
    columns.assign(A.columns.begin() + A.rowStart[i], A.columns.begin() + A.rowStart[i + 1]);
    std::sort(columns.begin(), columns.end());
    for (std::size_t k = 0; k < columns.size(); ++k) {
      if (columns[k] < 0 || columns[k] >= rows.nGlobal) {
        fatalError(fmt::format("distributed sparse system: row {} has column {} outside the rows [0, {})",
                               A.firstRow + i, columns[k], rows.nGlobal));
      }
      if (k > 0 && columns[k] == columns[k - 1]) {
        fatalError(fmt::format("sparse system: row {} has column {} twice", A.firstRow + i, columns[k]));
      }
    }
  }
}

void multiply(const SparseSystem& A, const std::vector<double>& x, std::vector<double>& y) {
  const int n = A.nRows();
  y.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    double sum = 0.0;
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
      sum += A.values[k] * x[A.columns[k] - A.firstRow];
    y[i] = sum;
  }
}

double norm2(const std::vector<double>& v) {
  double sum = 0.0;
  for (const double a : v) sum += a * a;
  return std::sqrt(sum);
}

double residualNorm(const SparseSystem& A, const std::vector<double>& x) {
  const int n = A.nRows();
  double sum = 0.0;
  for (int i = 0; i < n; ++i) {
    double r = A.rhs[i];
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k)
      r -= A.values[k] * x[A.columns[k] - A.firstRow];
    sum += r * r;
  }
  return std::sqrt(sum);
}

double normalisedResidual(const SparseSystem& A, const std::vector<double>& x) {
  return residualNorm(A, x) / std::max(norm2(A.rhs), std::numeric_limits<double>::min());
}

}  // namespace isph
