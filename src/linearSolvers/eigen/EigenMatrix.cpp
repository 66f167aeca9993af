#include "linearSolvers/eigen/EigenMatrix.hpp"

namespace isph {

EigenRowMatrix toEigen(const SparseSystem& A) {
  const int n = A.nRows();
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(A.values.size());
  for (int i = 0; i < n; ++i) {
    for (int k = A.rowStart[i]; k < A.rowStart[i + 1]; ++k) {
      entries.emplace_back(i, static_cast<int>(A.columns[k] - A.firstRow), A.values[k]);
    }
  }
  EigenRowMatrix M(n, n);
  M.setFromTriplets(entries.begin(), entries.end());
  return M;
}

}  // namespace isph
