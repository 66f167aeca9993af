#pragma once
// A square sparse linear system A x = b in CSR form, holding rows [firstRow, firstRow + nRows)
// of a global numbering. The pressure Poisson equation assembles A = -L, which has a positive
// diagonal and non-positive off-diagonals (numerics.md §1), and b = -S.
//
// Within a row, column indices must be distinct (the order is free). On one rank every
// column lies in [firstRow, firstRow + nRows). In a parallel run (doc/parallel.md) each rank
// holds its own rows only, as one block of the global numbering (GlobalNumbering: rank r's
// block follows rank r-1's), and its columns may be any rank's rows; only the hypre solvers
// take such a system.
#include <vector>

namespace isph {

// A global row or column number: hypre's HYPRE_BigInt, which Debian builds as int (32 bits:
// hypre itself then takes at most 2^31 - 1 rows), so that the columns go to hypre as they are,
// without a copy (at 640k particles the PPE's columns as long took 107 MB, their copy for
// hypre another 54 MB; doc/notes/scaling.md).
using GlobalIndex = int;

struct SparseSystem {
  long firstRow = 0;          // global index of local row 0 (a HYPRE_BigInt range)
  std::vector<int> rowStart;  // size nRows + 1; row i is entries [rowStart[i], rowStart[i+1])
  std::vector<GlobalIndex> columns;  // global column indices
  std::vector<double> values;
  std::vector<double> rhs;
  bool symmetricHint = true;  // the assembler's promise that A is symmetric (PCG is valid)

  int nRows() const { return rowStart.empty() ? 0 : static_cast<int>(rowStart.size()) - 1; }
  long nNonZeros() const { return rowStart.empty() ? 0 : rowStart.back(); }
};

// FatalError when the arrays do not describe a square CSR system (sizes, ranges, repeated
// columns in a row, non-finite values). O(nnz); every solver calls it before solving.
void checkSparseSystem(const SparseSystem& A);
// The same for this rank's block of a distributed system (collective): the blocks follow one
// another from row 0, and every column is a row of some rank.
void checkDistributedSparseSystem(const SparseSystem& A);

// y = A x (local rows; x is indexed by local row, x[c - firstRow]).
void multiply(const SparseSystem& A, const std::vector<double>& x, std::vector<double>& y);

// Euclidean norm.
double norm2(const std::vector<double>& v);

// ||b - A x||_2, by our own CSR mat-vec so that every solver is judged alike.
double residualNorm(const SparseSystem& A, const std::vector<double>& x);

// The residual every solver reports: ||b - A x||_2 / max(||b||_2, tiny).
double normalisedResidual(const SparseSystem& A, const std::vector<double>& x);

}  // namespace isph
