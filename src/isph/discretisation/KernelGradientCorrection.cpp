#include "isph/discretisation/KernelGradientCorrection.hpp"

#include <Eigen/LU>

namespace isph {

void KernelGradientCorrection::update(const ParticleSystem& ps, bool enabled, double minDeterminant) {
  const std::size_t n = ps.size();
  L_.assign(n, Eigen::Matrix3d::Identity());
  if (!enabled) {
    fallbacks_ = 0;
    return;
  }
  const auto& x = ps.cloud.positions;
  const auto& nl = ps.neighbours;
  const int dim = ps.dimension;
  const long active = static_cast<long>(ps.nMaterial);
  long fallbacks = 0;
#pragma omp parallel for schedule(static) reduction(+ : fallbacks)
  for (long a = 0; a < active; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    for (long k = nl.start[ua]; k < nl.start[ua + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto b = static_cast<std::size_t>(nl.index[kk]);
      const Vec3 xab = x[ua] - x[b];
      // V_b ∇_a W_ab ⊗ (x_b − x_a) = −V_b F x_ab ⊗ x_ab
      M.noalias() -= ps.volume[b] * nl.F[kk] * (xab * xab.transpose());
    }
    if (dim == 2) M(2, 2) = 1.0;
    const double det = M.determinant();
    if (det > minDeterminant) {
      L_[ua] = M.inverse();
      if (dim == 2) {
        L_[ua](0, 2) = L_[ua](1, 2) = L_[ua](2, 0) = L_[ua](2, 1) = 0.0;
        L_[ua](2, 2) = 1.0;
      }
    } else {
      ++fallbacks;
    }
  }
  fallbacks_ = static_cast<std::size_t>(fallbacks);
}

}  // namespace isph
