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
  checkSizes(A);
  const GlobalNumbering rows = GlobalNumbering::of(A.nRows());
  if (A.firstRow != rows.first) {
    fatalError(fmt::format("distributed sparse system: this rank's rows start at {}, but the ranks before it "
                           "hold {} rows",
                           A.firstRow, rows.first));
  }
  // One pass, as checkSparseSystem: this rank's columns marked by row (lastSeen), the few of
  // other ranks' rows (a row beside the cut) sorted apart. (A sort of every row made the checks
  // slower on two ranks than on one: 0.32 s against 0.25 s in the scaling benchmark's 40k column.)
  const int n = A.nRows();
  std::vector<int> lastSeen(static_cast<std::size_t>(n), -1);
  std::vector<GlobalIndex> others;
  for (int i = 0; i < n; ++i) {
    checkRowStart(A, i);
    others.clear();
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      checkFinite(A, i, k);
      const GlobalIndex column = A.columns[k];
      if (column < 0 || column >= rows.nGlobal) {
        fatalError(fmt::format("distributed sparse system: row {} has column {} outside the rows [0, {})",
                               A.firstRow + i, column, rows.nGlobal));
      }
      const long c = column - A.firstRow;
      if (c < 0 || c >= n) {
        others.push_back(column);
        continue;
      }
      if (lastSeen[c] == i) {
        fatalError(fmt::format("sparse system: row {} has column {} twice", A.firstRow + i, column));
      }
      lastSeen[c] = i;
    }
    std::sort(others.begin(), others.end());
    for (std::size_t k = 1; k < others.size(); ++k) {
      if (others[k] == others[k - 1]) {
        fatalError(fmt::format("sparse system: row {} has column {} twice", A.firstRow + i, others[k]));
      }
    }
    checkFiniteRhs(A, i);
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
