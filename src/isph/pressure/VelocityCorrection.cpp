#include "isph/pressure/VelocityCorrection.hpp"

#include "isph/walls/WallBoundaryPressure.hpp"

namespace isph {

Vec3 pressureGradient(const ParticleSystem& ps, const KernelGradientCorrection& L, const std::vector<Vec3>& ustar,
                      const Vec3& g, std::size_t a, double dt) {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  Vec3 sum = Vec3::Zero();
  for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const auto b = static_cast<std::size_t>(nl.index[kk]);
    const double dp = ps.isMaterial(b) ? c.p[b] - c.p[a] : wallPressureIncrement(ps, ustar, g, a, b, dt);
    sum += ps.volume[b] * dp * nl.F[kk] * (c.positions[a] - c.positions[b]);
  }
  return L[a] * sum;
}

void correctVelocity(ParticleSystem& ps, const KernelGradientCorrection& L, const std::vector<Vec3>& ustar,
                     const Vec3& g, double dt) {
  const long n = static_cast<long>(ps.nMaterial);
  std::vector<Vec3> U(ps.nMaterial);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    U[ua] = ustar[ua] - dt / ps.rho[ua] * pressureGradient(ps, L, ustar, g, ua, dt);  // Eq. 11
  }
  std::copy(U.begin(), U.end(), ps.cloud.U.begin());
}

}  // namespace isph
