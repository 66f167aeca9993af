#pragma once
// A SparseSystem handed to hypre through its IJ interface, by global row numbers: the matrix in
// ONE HYPRE_IJMatrixSetValues call with the CSR arrays (row-by-row calls cost as much as the
// solve), and the vectors b and x. In a parallel run each rank sets its own block of rows
// (never another rank's: off-rank values go through hypre's slow stash, hypre issue 226), and
// together they make one ParCSR matrix, each row's columns split into those of the rank's
// block (the diagonal part) and the others (off-diagonal), as hypre wants them preallocated.
// Everything is freed by the destructors.
#include <HYPRE.h>
#include <HYPRE_IJ_mv.h>
#include <HYPRE_parcsr_mv.h>

#include <memory>
#include <type_traits>
#include <vector>

#include "linearSolvers/SparseSystem.hpp"

namespace isph {

class HypreVector;

class HypreMatrix {
 public:
  explicit HypreMatrix(const SparseSystem& A);
  HypreMatrix(const HypreMatrix&) = delete;
  HypreMatrix& operator=(const HypreMatrix&) = delete;

  HYPRE_ParCSRMatrix parcsr() const { return parcsr_; }
  // ||b - A x||_2 over all ranks, x given as this rank's block (rows from firstRow); collective.
  double residualNorm(const HypreVector& b, long firstRow, const std::vector<double>& x) const;

 private:
  std::unique_ptr<std::remove_pointer_t<HYPRE_IJMatrix>, HYPRE_Int (*)(HYPRE_IJMatrix)> ij_{
      nullptr, HYPRE_IJMatrixDestroy};
  HYPRE_ParCSRMatrix parcsr_ = nullptr;
};

class HypreVector {
 public:
  // Rows [firstRow, firstRow + values.size()).
  HypreVector(long firstRow, const std::vector<double>& values);
  HypreVector(const HypreVector&) = delete;
  HypreVector& operator=(const HypreVector&) = delete;

  HYPRE_ParVector par() const { return par_; }
  void copyTo(std::vector<double>& values) const;

 private:
  std::vector<HYPRE_BigInt> rows_;
  std::unique_ptr<std::remove_pointer_t<HYPRE_IJVector>, HYPRE_Int (*)(HYPRE_IJVector)> ij_{
      nullptr, HYPRE_IJVectorDestroy};
  HYPRE_ParVector par_ = nullptr;
};

}  // namespace isph
