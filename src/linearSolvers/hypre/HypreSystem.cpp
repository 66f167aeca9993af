#include "linearSolvers/hypre/HypreSystem.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <numeric>
#include <type_traits>

#include "core/Error.hpp"
#include "linearSolvers/hypre/HypreError.hpp"

namespace isph {

namespace {

// hypre's global indices are HYPRE_BigInt (int in Debian's build): check the range fits.
void checkRange(long first, long n) {
  if (first < 0 || first + n - 1 > std::numeric_limits<HYPRE_BigInt>::max()) {
    fatalError(fmt::format("hypre: rows [{}, {}) do not fit hypre's {}-byte global indices", first,
                           first + n, sizeof(HYPRE_BigInt)));
  }
}

std::vector<HYPRE_BigInt> rowNumbers(long first, std::size_t n) {
  std::vector<HYPRE_BigInt> rows(n);
  std::iota(rows.begin(), rows.end(), static_cast<HYPRE_BigInt>(first));
  return rows;
}

}  // namespace

HypreMatrix::HypreMatrix(const SparseSystem& A) {
  const int n = A.nRows();
  checkRange(A.firstRow, n);
  const auto first = static_cast<HYPRE_BigInt>(A.firstRow);
  const HYPRE_BigInt last = first + n - 1;

  std::vector<HYPRE_Int> rowSizes(static_cast<std::size_t>(n)), diagSizes(rowSizes), offdSizes(rowSizes);
  for (int i = 0; i < n; ++i) {
    rowSizes[i] = A.rowStart[i + 1] - A.rowStart[i];
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      const bool own = A.columns[k] >= A.firstRow && A.columns[k] < A.firstRow + n;
      ++(own ? diagSizes : offdSizes)[static_cast<std::size_t>(i)];
    }
  }
  const std::vector<HYPRE_BigInt> rows = rowNumbers(A.firstRow, rowSizes.size());
  // The columns as they are where hypre's global index is ours (Debian's int), else a copy.
  std::vector<HYPRE_BigInt> converted;
  const HYPRE_BigInt* cols = nullptr;
  if constexpr (std::is_same_v<HYPRE_BigInt, GlobalIndex>) {
    cols = A.columns.data();
  } else {
    converted.assign(A.columns.begin(), A.columns.end());
    cols = converted.data();
  }

  HYPRE_IJMatrix ij = nullptr;
  hypreCheck(HYPRE_IJMatrixCreate(MPI_COMM_WORLD, first, last, first, last, &ij),
             "HYPRE_IJMatrixCreate");
  ij_.reset(ij);
  hypreCheck(HYPRE_IJMatrixSetObjectType(ij, HYPRE_PARCSR), "HYPRE_IJMatrixSetObjectType");
  hypreCheck(HYPRE_IJMatrixSetDiagOffdSizes(ij, diagSizes.data(), offdSizes.data()),
             "HYPRE_IJMatrixSetDiagOffdSizes");
  hypreCheck(HYPRE_IJMatrixInitialize(ij), "HYPRE_IJMatrixInitialize");
  // All rows in one call, straight from the CSR arrays (ncols is not const in hypre's API).
  hypreCheck(
      HYPRE_IJMatrixSetValues(ij, n, rowSizes.data(), rows.data(), cols, A.values.data()),
      "HYPRE_IJMatrixSetValues");
  hypreCheck(HYPRE_IJMatrixAssemble(ij), "HYPRE_IJMatrixAssemble");
  void* object = nullptr;
  hypreCheck(HYPRE_IJMatrixGetObject(ij, &object), "HYPRE_IJMatrixGetObject");
  parcsr_ = static_cast<HYPRE_ParCSRMatrix>(object);
}

HypreVector::HypreVector(long firstRow, const std::vector<double>& values)
    : rows_(rowNumbers(firstRow, values.size())) {
  const auto n = static_cast<long>(values.size());
  checkRange(firstRow, n);
  const auto first = static_cast<HYPRE_BigInt>(firstRow);
  HYPRE_IJVector ij = nullptr;
  hypreCheck(
      HYPRE_IJVectorCreate(MPI_COMM_WORLD, first, static_cast<HYPRE_BigInt>(first + n - 1), &ij),
      "HYPRE_IJVectorCreate");
  ij_.reset(ij);
  hypreCheck(HYPRE_IJVectorSetObjectType(ij, HYPRE_PARCSR), "HYPRE_IJVectorSetObjectType");
  hypreCheck(HYPRE_IJVectorInitialize(ij), "HYPRE_IJVectorInitialize");
  hypreCheck(HYPRE_IJVectorSetValues(ij, static_cast<HYPRE_Int>(n), rows_.data(), values.data()),
             "HYPRE_IJVectorSetValues");
  hypreCheck(HYPRE_IJVectorAssemble(ij), "HYPRE_IJVectorAssemble");
  void* object = nullptr;
  hypreCheck(HYPRE_IJVectorGetObject(ij, &object), "HYPRE_IJVectorGetObject");
  par_ = static_cast<HYPRE_ParVector>(object);
}

double HypreMatrix::residualNorm(const HypreVector& b, long firstRow, const std::vector<double>& x) const {
  const HypreVector xh(firstRow, x);
  HypreVector r(firstRow, std::vector<double>(x.size()));
  hypreCheck(HYPRE_ParVectorCopy(b.par(), r.par()), "HYPRE_ParVectorCopy");
  hypreCheck(HYPRE_ParCSRMatrixMatvec(-1.0, parcsr_, xh.par(), 1.0, r.par()), "HYPRE_ParCSRMatrixMatvec");
  double rr = 0;
  hypreCheck(HYPRE_ParVectorInnerProd(r.par(), r.par(), &rr), "HYPRE_ParVectorInnerProd");
  return std::sqrt(rr);
}

void HypreVector::copyTo(std::vector<double>& values) const {
  values.resize(rows_.size());
  hypreCheck(HYPRE_IJVectorGetValues(ij_.get(), static_cast<HYPRE_Int>(rows_.size()), rows_.data(),
                                     values.data()),
             "HYPRE_IJVectorGetValues");
}

}  // namespace isph
