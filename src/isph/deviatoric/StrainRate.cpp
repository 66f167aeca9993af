#include "isph/deviatoric/StrainRate.hpp"

#include <cmath>

#include "isph/discretisation/MaterialGradient.hpp"

namespace isph {

double shearRateMagnitude(const SymmTensor& D) {
  return std::sqrt(2.0 * doubleDotSymm(D));
}

void StrainRate::compute(const ParticleSystem& ps, const MaterialTable& materials,
                         const KernelGradientCorrection& correction, double minDeterminant) {
  compute(ps, materials, correction, minDeterminant, ps.cloud.U);
}

void StrainRate::compute(const ParticleSystem& ps, const MaterialTable& materials,
                         const KernelGradientCorrection& correction, double minDeterminant,
                         const std::vector<Vec3>& u) {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const std::size_t n = ps.size();
  D.assign(n, SymmTensor::Zero());
  shearRate.assign(n, 0.0);
  const int dim = ps.dimension;
  const long nMat = static_cast<long>(ps.nMaterial);
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < nMat; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    const bool withWalls = materials[static_cast<std::size_t>(c.material[a])].wallContact() == WallContact::noSlip;
    Eigen::Matrix3d G = Eigen::Matrix3d::Zero();  // Σ V_b (u_b − u_a) ⊗ ∇W
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto b = static_cast<std::size_t>(nl.index[kk]);
      const bool material = ps.isMaterial(b);
      if (!material && !withWalls) continue;
      const Vec3 xab = c.positions[a] - c.positions[b];
      const Vec3 gradW = nl.F[kk] * xab;
      const Vec3 ub = material ? u[b] : Vec3::Zero();
      G.noalias() += ps.volume[b] * (ub - u[a]) * gradW.transpose();
    }
    // ∂u_i/∂x_j; renormalised over what the sum ran over (walls add their moment for noSlip).
    Eigen::Matrix3d gradU = G;
    if (withWalls) {
      gradU = G * correction[a].transpose();  // L_a = (M_aᵀ)⁻¹ over all neighbours
    } else {
      gradU = G * materialMomentInverse(ps, a, minDeterminant);
    }
    if (dim == 2) gradU.row(2).setZero(), gradU.col(2).setZero();
    Eigen::Matrix3d d = 0.5 * (gradU + gradU.transpose());
    d.diagonal().array() -= d.trace() / 3.0;  // deviatoric (Eq. 5; plane strain keeps D_zz)
    SymmTensor& s = D[a];
    s << d(0, 0), d(0, 1), d(0, 2), d(1, 1), d(1, 2), d(2, 2);
    shearRate[a] = shearRateMagnitude(s);
  }
}

}  // namespace isph
