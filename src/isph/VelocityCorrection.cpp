#include "isph/VelocityCorrection.hpp"

#include "isph/WallBoundaryPressure.hpp"

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
                     const Vec3& g, double dt, const Kernel* symmetric) {
  const long n = static_cast<long>(ps.nMaterial);
  std::vector<Vec3> U(ps.nMaterial);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    U[ua] = symmetric ? Vec3(ustar[ua] + dt * laggedPressureForce(ps, *symmetric, ustar, g, ua, dt))  // Eq. 11
                      : Vec3(ustar[ua] - dt / ps.rho[ua] * pressureGradient(ps, L, ustar, g, ua, dt));
  }
  std::copy(U.begin(), U.end(), ps.cloud.U.begin());
}

Vec3 laggedPressureForce(const ParticleSystem& ps, const Kernel& kernel, const std::vector<Vec3>& ustar,
                         const Vec3& g, std::size_t a, double dt, Vec3* frictionReaction) {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const double qa = c.p[a] / (ps.rho[a] * ps.rho[a]);
  Vec3 sum = Vec3::Zero(), reaction = Vec3::Zero();
  for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const auto b = static_cast<std::size_t>(nl.index[kk]);
    const double mb = ps.rho[b] * ps.volume[b];
    if (ps.isMaterial(b)) {
      sum -= mb * (qa + c.p[b] / (ps.rho[b] * ps.rho[b])) * nl.F[kk] * (c.positions[a] - c.positions[b]);
      continue;
    }
    // The wall layers as if on the material's lattice (latticePosition: the symmetric form is
    // consistent only for a complete lattice). Their pressure is the wall condition there.
    const Vec3& n = wallNormal(ps, b);
    const Vec3 xb = latticePosition(ps, b);
    const Vec3 rba = xb - c.positions[a];
    const double r = rba.norm();
    if (r <= 0 || r >= kernel.supportRadius()) continue;
    const WallPressureParts parts = wallPressureParts(ps, ustar, g, a, b, rba, dt);
    const double pb = c.p[a] + parts.normal + parts.tangential;
    // A wall pushes along its normal only: the tangential traction is the friction's.
    const Vec3 f = mb * (qa + pb / (ps.rho[b] * ps.rho[b])) * kernel.dWdr(r) / r * rba;
    const Vec3 fn = f.dot(n) * n;
    sum += fn;
    if (ps.frictionWall[b]) reaction += fn;
  }
  if (frictionReaction) *frictionReaction = c.mass[a] * reaction;
  return sum;
}

void correctVelocityIncrement(ParticleSystem& ps, const KernelGradientCorrection& L, const std::vector<Vec3>& ustar,
                              const std::vector<double>& increment, double dt) {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const long n = static_cast<long>(ps.nMaterial);
  std::vector<Vec3> U(ps.nMaterial);
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < n; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    Vec3 sum = Vec3::Zero();
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto b = static_cast<std::size_t>(nl.index[kk]);
      const double d = ps.isMaterial(b) ? increment[b] - increment[a]
                                        : wallPressureIncrementOfIncrement(ps, ustar, a, b, dt);
      sum += ps.volume[b] * d * nl.F[kk] * (c.positions[a] - c.positions[b]);
    }
    U[a] = ustar[a] - dt / ps.rho[a] * (L[a] * sum);  // Eq. 11 on the increment
  }
  std::copy(U.begin(), U.end(), ps.cloud.U.begin());
}

}  // namespace isph
