#include "isph/deviatoric/IntermediateVelocity.hpp"

#include <algorithm>

#include "parallel/Reduce.hpp"

namespace isph {

double IntermediateVelocity::compute(const ParticleSystem& ps, const MaterialTable& materials,
                                     const std::vector<double>& eta, const Vec3& g, double dt, double h,
                                     std::vector<Vec3>& ustar) {
  const auto& c = ps.cloud;
  ustar.assign(ps.size(), Vec3::Zero());
  const bool viscous = !eta.empty();
  const auto& nl = ps.neighbours;
  const double eta2 = 0.01 * h * h;
  const long n = static_cast<long>(ps.nMaterial);
  double maxAccel = 0;
#pragma omp parallel for schedule(static) reduction(max : maxAccel)
  for (long a = 0; a < n; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    Vec3 accel = Vec3::Zero();
    if (viscous) {
      const bool withWalls =
          materials[static_cast<std::size_t>(c.material[ua])].wallContact() == WallContact::noSlip;
      for (long k = nl.start[ua]; k < nl.start[ua + 1]; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        const auto b = static_cast<std::size_t>(nl.index[kk]);
        const bool material = ps.isMaterial(b);
        if (!material && !withWalls) continue;
        const double etaB = material ? eta[b] : eta[ua];
        const Vec3 ub = material ? c.U[b] : Vec3::Zero();
        const double r2 = (c.positions[ua] - c.positions[b]).squaredNorm();
        const double mb = ps.rho[b] * ps.volume[b];
        accel += mb * (eta[ua] + etaB) / (ps.rho[ua] * ps.rho[b]) * nl.F[kk] * r2 / (r2 + eta2) * (c.U[ua] - ub);
      }
      if (ua < ps.ownMaterial()) maxAccel = std::max(maxAccel, accel.norm());  // (parallel: the own)
    }
    ustar[ua] = c.U[ua] + dt * (g + accel);  // Eq. 6
  }
  return maxOverRanks(maxAccel);
}

}  // namespace isph
