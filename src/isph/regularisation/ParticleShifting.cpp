#include "isph/regularisation/ParticleShifting.hpp"

#include <algorithm>
#include <cmath>

#include "isph/discretisation/MaterialGradient.hpp"
#include "isph/parallel/GhostExchange.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

namespace {

// (∇u)_ij = ∂u_i/∂x_j and ∇p of material particle a over its material neighbours, renormalised
// with the material moment's inverse Minv (MaterialGradient).
struct MaterialGradients {
  Eigen::Matrix3d U = Eigen::Matrix3d::Zero();
  Vec3 p = Vec3::Zero();
};
MaterialGradients materialGradients(const ParticleSystem& ps, std::size_t a, const Eigen::Matrix3d& Minv) {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  MaterialGradients g;
  for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const auto b = static_cast<std::size_t>(nl.index[kk]);
    if (!ps.isMaterial(b)) continue;
    const Vec3 gw = Minv.transpose() * (nl.F[kk] * (c.positions[a] - c.positions[b]));
    g.U.noalias() += ps.volume[b] * (c.U[b] - c.U[a]) * gw.transpose();
    g.p += ps.volume[b] * (c.p[b] - c.p[a]) * gw;
  }
  return g;
}

}  // namespace

double deformationSpeed(const ParticleSystem& ps, const Kernel& kernel, std::size_t a, double correctionMinDeterminant) {
  const Eigen::Matrix3d gradU =
      materialGradients(ps, a, materialMomentInverse(ps, a, correctionMinDeterminant)).U;
  const Eigen::Matrix3d D = 0.5 * (gradU + gradU.transpose());
  return kernel.h() * std::sqrt(2.0 * D.squaredNorm());  // h |γ̇|, |γ̇| = √(2 D:D)
}

ShiftingResult shiftParticles(ParticleSystem& ps, const Kernel& kernel, const std::vector<char>& freeSurface,
                              const ShiftingSettings& settings, double correctionMinDeterminant, bool tensionCutoff,
                              double dt) {
  auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const long n = static_cast<long>(ps.nMaterial);
  const double Wdx = kernel.W(ps.dx);
  const double maxShift = settings.maxShift * ps.dx;
  std::vector<Vec3> shift(ps.nMaterial, Vec3::Zero());
  double largest = 0;
  long capped = 0;
#pragma omp parallel for schedule(static) reduction(max : largest) reduction(+ : capped)
  for (long a = 0; a < n; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    const double speed =
        settings.deformationSpeed ? deformationSpeed(ps, kernel, ua, correctionMinDeterminant) : c.U[ua].norm();
    // Free-surface particles are not shifted: at the tip of a front the tangent of the
    // surface runs along the flow, and shifting there drives a jet ahead of the front
    // (the dam break's front speed was 23% high with it, 0.4% low without).
    if (speed == 0 || freeSurface[ua]) continue;
    Vec3 gradC = Vec3::Zero();
    Vec3 gradPair = Vec3::Zero();  // the pair term alone, above its lattice value (nearSurface pairs)
    bool nearSurface = freeSurface[ua];
    double nearestWall2 = 1e300;
    std::size_t wall = 0;
    for (long k = nl.start[ua]; k < nl.start[ua + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto b = static_cast<std::size_t>(nl.index[kk]);
      const double ratio = nl.W[kk] / Wdx;
      gradC += ps.volume[b] * (1.0 + 0.2 * ratio * ratio * ratio * ratio) * nl.F[kk] * (c.positions[ua] - c.positions[b]);
      if (settings.pairsNearSurface && ratio > 1.0 && ps.isMaterial(b)) {
        gradPair += ps.volume[b] * 0.2 * (ratio * ratio * ratio * ratio - 1.0) * nl.F[kk] * (c.positions[ua] - c.positions[b]);
      }
      nearSurface = nearSurface || (ps.isMaterial(b) && freeSurface[b]);
      if (ps.isWall(b) && (c.positions[ua] - c.positions[b]).squaredNorm() < nearestWall2) {
        nearestWall2 = (c.positions[ua] - c.positions[b]).squaredNorm();
        wall = b;
      }
    }
    const double D = settings.coefficient * kernel.h() * speed * dt;
    Vec3 dr = -D * gradC;
    if (nearSurface && settings.pairsNearSurface) {
      dr = -D * gradPair;
    } else if (nearSurface && gradC.squaredNorm() > 0) {  // removes all of it (see the header)
      const Vec3 normal = -gradC.normalized();
      dr -= dr.dot(normal) * normal;
    }
    // Next to a wall, only along it: the wall particles sit half a spacing from the first
    // material row (particleMesh), so ∇C there points into the wall, and shifting along it
    // would lift the flow off the bed a little every step.
    if (nearestWall2 < 1e300) {
      const Vec3& n = c.normal[wall];
      dr -= dr.dot(n) * n;
    }
    const double len = dr.norm();
    if (len > maxShift) {
      dr *= maxShift / len;
      capped += ua < ps.ownMaterial();
    }
    shift[ua] = dr;
    if (ua < ps.ownMaterial()) largest = std::max(largest, std::min(len, maxShift) / ps.dx);  // (parallel: the own)
  }

  // Taylor correction of u and p, then move. The gradients are over material neighbours
  // only, renormalised with the material moment (MaterialGradient): a wall particle carries
  // no velocity of the material (u_w = 0 would read as a shear, and with the moment of a cut
  // support as a spurious ∂u/∂x, which accelerated a block sliding on a Coulomb bed).
  std::vector<Vec3> Unew(c.U.begin(), c.U.begin() + n);
  std::vector<double> pnew(c.p.begin(), c.p.begin() + n);
#pragma omp parallel for schedule(static)
  for (long a = 0; a < n; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    if (shift[ua].squaredNorm() == 0) continue;
    const MaterialGradients grad = materialGradients(ps, ua, materialMomentInverse(ps, ua, correctionMinDeterminant));
    Unew[ua] += grad.U * shift[ua];
    pnew[ua] += grad.p.dot(shift[ua]);
    // The tension cut-off holds after the shift too: next to a pressure spike the Taylor term
    // alone gave p = −54 kPa (20× the column's lithostatic pressure) and the lagged pressure
    // gradient of the wall friction then blew the 2 mm column collapse up.
    if (tensionCutoff) pnew[ua] = std::max(pnew[ua], 0.0);
  }
  for (long a = 0; a < n; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    c.positions[ua] += shift[ua];
    c.U[ua] = Unew[ua];
    c.p[ua] = pnew[ua];
  }
  exchangeGhosts(ps, c.positions);  // parallel: the collisions read them at ghosts
  exchangeGhosts(ps, c.U);
  exchangeGhosts(ps, c.p);
  return {maxOverRanks(largest), sumOverRanks(static_cast<std::size_t>(capped))};
}

}  // namespace isph
