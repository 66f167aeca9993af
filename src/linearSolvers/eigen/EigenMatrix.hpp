#pragma once
// A SparseSystem as Eigen matrices and vectors (local numbering: column c - firstRow).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "linearSolvers/SparseSystem.hpp"

namespace isph {

using EigenRowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// The matrix, row-major (what Eigen's CG and BiCGSTAB parallelise), columns sorted.
EigenRowMatrix toEigen(const SparseSystem& A);

// Views of std::vector data as Eigen vectors.
inline Eigen::Map<const Eigen::VectorXd> asEigen(const std::vector<double>& v) {
  return {v.data(), static_cast<Eigen::Index>(v.size())};
}
inline Eigen::Map<Eigen::VectorXd> asEigen(std::vector<double>& v) {
  return {v.data(), static_cast<Eigen::Index>(v.size())};
}

}  // namespace isph
