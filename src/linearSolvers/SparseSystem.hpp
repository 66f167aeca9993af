#pragma once
// A square sparse linear system A x = b in CSR form, holding rows [firstRow, firstRow + nRows)
// of a global numbering (one rank for now; the global numbering keeps an MPI decomposition
// possible later). The pressure Poisson equation assembles A = -L, which has a positive
// diagonal and non-positive off-diagonals (numerics.md §1), and b = -S.
//
// Within a row, column indices must be distinct (the order is free). On one rank every
// column lies in [firstRow, firstRow + nRows).
#include <vector>

namespace isph {

struct SparseSystem {
  long firstRow = 0;          // global index of local row 0 (a HYPRE_BigInt range)
  std::vector<int> rowStart;  // size nRows + 1; row i is entries [rowStart[i], rowStart[i+1])
  std::vector<long> columns;  // global column indices
  std::vector<double> values;
  std::vector<double> rhs;
  bool symmetricHint = true;  // the assembler's promise that A is symmetric (PCG is valid)

  int nRows() const { return rowStart.empty() ? 0 : static_cast<int>(rowStart.size()) - 1; }
  long nNonZeros() const { return rowStart.empty() ? 0 : rowStart.back(); }
};

// FatalError when the arrays do not describe a square CSR system (sizes, ranges, repeated
// columns in a row, non-finite values). O(nnz); every solver calls it before solving.
void checkSparseSystem(const SparseSystem& A);

// y = A x (local rows; x is indexed by local row, x[c - firstRow]).
void multiply(const SparseSystem& A, const std::vector<double>& x, std::vector<double>& y);

// Euclidean norm.
double norm2(const std::vector<double>& v);

// ||b - A x||_2, by our own CSR mat-vec so that every solver is judged alike.
double residualNorm(const SparseSystem& A, const std::vector<double>& x);

// The residual every solver reports: ||b - A x||_2 / max(||b||_2, tiny).
double normalisedResidual(const SparseSystem& A, const std::vector<double>& x);

}  // namespace isph
