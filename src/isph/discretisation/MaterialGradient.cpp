#include "isph/discretisation/MaterialGradient.hpp"

#include <Eigen/LU>

namespace isph {

Eigen::Matrix3d materialMomentInverse(const ParticleSystem& ps, std::size_t a, double minDeterminant) {
  const auto& nl = ps.neighbours;
  const auto& x = ps.cloud.positions;
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const auto b = static_cast<std::size_t>(nl.index[kk]);
    if (!ps.isMaterial(b)) continue;
    const Vec3 xab = x[a] - x[b];
    M.noalias() -= ps.volume[b] * nl.F[kk] * (xab * xab.transpose());  // (x_b − x_a) ⊗ ∇W
  }
  if (ps.dimension == 2) M(2, 2) = 1.0;
  if (!(M.determinant() > minDeterminant)) return Eigen::Matrix3d::Identity();
  Eigen::Matrix3d inv = M.inverse();
  if (ps.dimension == 2) {
    inv.row(2).setZero();
    inv.col(2).setZero();
    inv(2, 2) = 1.0;
  }
  return inv;
}

std::vector<Vec3> materialPressureGradient(const ParticleSystem& ps, double minDeterminant) {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const long n = static_cast<long>(ps.nMaterial);
  std::vector<Vec3> grad(ps.nMaterial, Vec3::Zero());
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < n; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    Vec3 sum = Vec3::Zero();
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto b = static_cast<std::size_t>(nl.index[kk]);
      if (ps.isMaterial(b)) sum += ps.volume[b] * (c.p[b] - c.p[a]) * nl.F[kk] * (c.positions[a] - c.positions[b]);
    }
    grad[a] = materialMomentInverse(ps, a, minDeterminant).transpose() * sum;
  }
  return grad;
}

}  // namespace isph
