#include "isph/solvers/WeaklyCompressibleStep.hpp"

#include <algorithm>
#include <cmath>

#include "isph/walls/WallBoundaryPressure.hpp"

namespace isph {

namespace {

// x_a − x_b and the gradient factor of a pair, boundary particles at their lattice positions
// (WallBoundaryPressure.hpp): the symmetric sums are consistent only on a complete lattice.
struct PairGeometry {
  Vec3 x = Vec3::Zero();
  double F = 0;
};

PairGeometry pairGeometry(const ParticleSystem& ps, const Kernel& kernel, std::size_t a, std::size_t b,
                          std::size_t k) {
  if (ps.isMaterial(a) && ps.isMaterial(b)) return {ps.cloud.positions[a] - ps.cloud.positions[b], ps.neighbours.F[k]};
  const Vec3 x = latticePosition(ps, a) - latticePosition(ps, b);
  const double r = x.norm();
  if (r <= 0 || r >= kernel.supportRadius()) return {x, 0.0};
  return {x, kernel.dWdr(r) / r};
}

}  // namespace

WeaklyCompressibleStep::WeaklyCompressibleStep(const WcsphSettings& settings, bool tensionCutoff, double soundSpeed)
    : c0_(soundSpeed),
      delta_(settings.densityDiffusion),
      alpha_(settings.artificialViscosity),
      tensionCutoff_(tensionCutoff) {}

void WeaklyCompressibleStep::initialiseDensity(const ParticleSystem& ps) {
  density_.resize(ps.size());
  for (std::size_t a = 0; a < ps.size(); ++a) density_[a] = ps.rho[a] + ps.cloud.p[a] / (c0_ * c0_);
}

void WeaklyCompressibleStep::permute(const std::vector<int>& order) {
  std::vector<double> old(density_.begin(), density_.begin() + static_cast<long>(order.size()));
  for (std::size_t i = 0; i < order.size(); ++i) density_[i] = old[static_cast<std::size_t>(order[i])];
}

double WeaklyCompressibleStep::pressure(const ParticleSystem& ps, std::size_t a) const {
  const double p = c0_ * c0_ * (density_[a] - ps.rho[a]);
  return tensionCutoff_ || !ps.isMaterial(a) ? std::max(p, 0.0) : p;  // walls never pull
}

void WeaklyCompressibleStep::updatePressure(ParticleSystem& ps) const {
  for (std::size_t a = 0; a < ps.nMaterial; ++a) ps.cloud.p[a] = pressure(ps, a);
}

std::vector<double> WeaklyCompressibleStep::densityRate(const ParticleSystem& ps, const Kernel& kernel, const Vec3& g,
                                                        double h) const {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const double eta2 = 0.01 * h * h;
  const double diffusion = delta_ * h * c0_;
  std::vector<double> rate(ps.size(), 0.0);
  const long n = static_cast<long>(ps.size());
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < n; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    const bool materialA = ps.isMaterial(a);
    const Vec3 ua = materialA ? c.U[a] : Vec3::Zero();  // walls at rest
    double div = 0, diff = 0;
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto b = static_cast<std::size_t>(nl.index[kk]);
      const bool materialB = ps.isMaterial(b);
      if (!materialA && !materialB) continue;  // walls among themselves: at rest
      const PairGeometry pair = pairGeometry(ps, kernel, a, b, kk);
      const Vec3& xab = pair.x;
      const Vec3 uab = ua - (materialB ? c.U[b] : Vec3::Zero());
      div += ps.rho[b] * ps.volume[b] * pair.F * uab.dot(xab);
      if (materialA && materialB && c.material[b] == c.material[a] && diffusion > 0) {
        const double r2 = xab.squaredNorm();
        const double psi = (density_[a] - density_[b]) - ps.rho[a] * g.dot(xab) / (c0_ * c0_);
        diff += 2 * psi * nl.F[kk] * r2 / (r2 + eta2) * ps.volume[b];
      }
    }
    rate[a] = div + diffusion * diff;  // Σ m_b u_ab·∇W: ρ_a Σ V_b u_ab·∇W with V_b = m_b/ρ_b
  }
  return rate;
}

Vec3 WeaklyCompressibleStep::pressureForce(const ParticleSystem& ps, const Kernel& kernel, std::size_t a) const {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const double qa = c.p[a] / (density_[a] * density_[a]);
  Vec3 sum = Vec3::Zero();
  for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const auto b = static_cast<std::size_t>(nl.index[kk]);
    const double mb = ps.rho[b] * ps.volume[b];
    const double pb = ps.isMaterial(b) ? c.p[b] : pressure(ps, b);
    const PairGeometry pair = pairGeometry(ps, kernel, a, b, kk);
    sum -= mb * (qa + pb / (density_[b] * density_[b])) * pair.F * pair.x;
  }
  return sum;
}

Vec3 WeaklyCompressibleStep::deviatoricForce(const ParticleSystem& ps, const Kernel& kernel,
                                             const std::vector<SymmTensor>& s, std::size_t a) const {
  const auto& nl = ps.neighbours;
  const double ra2 = density_[a] * density_[a];
  Vec3 sum = Vec3::Zero();
  for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const auto b = static_cast<std::size_t>(nl.index[kk]);
    const double mb = ps.rho[b] * ps.volume[b];
    const double rb2 = density_[b] * density_[b];
    const PairGeometry pair = pairGeometry(ps, kernel, a, b, kk);
    const Vec3 gradW = pair.F * pair.x;
    if (ps.isMaterial(b)) {
      sum += mb * (dotSymm(s[a], gradW) / ra2 + dotSymm(s[b], gradW) / rb2);
    } else {
      const Vec3& n = wallNormal(ps, b);
      sum += mb * (1.0 / ra2 + 1.0 / rb2) * dotSymm(s[a], gradW).dot(n) * n;
    }
  }
  return sum;
}

Vec3 WeaklyCompressibleStep::artificialViscosity(const ParticleSystem& ps, double h, std::size_t a) const {
  if (alpha_ <= 0) return Vec3::Zero();
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const double eta2 = 0.01 * h * h;
  Vec3 accel = Vec3::Zero();
  for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const auto b = static_cast<std::size_t>(nl.index[kk]);
    if (!ps.isMaterial(b)) continue;
    const Vec3 xab = c.positions[a] - c.positions[b];
    const double ux = (c.U[a] - c.U[b]).dot(xab);
    if (ux >= 0) continue;  // separating pairs feel none
    const double mu = h * ux / (xab.squaredNorm() + eta2);
    const double pi = -alpha_ * c0_ * mu / (0.5 * (density_[a] + density_[b]));
    accel -= ps.rho[b] * ps.volume[b] * pi * nl.F[kk] * xab;
  }
  return accel;
}

void WeaklyCompressibleStep::advanceDensity(const std::vector<double>& rate, double dt) {
  for (std::size_t a = 0; a < density_.size(); ++a) density_[a] += dt * rate[a];
}

double WeaklyCompressibleStep::maxDensityVariation(const ParticleSystem& ps) const {
  double v = 0;
  for (std::size_t a = 0; a < ps.nMaterial; ++a) v = std::max(v, std::abs(density_[a] / ps.rho[a] - 1));
  return v;
}

std::pair<double, std::size_t> WeaklyCompressibleStep::maxCompression(const ParticleSystem& ps) const {
  std::pair<double, std::size_t> worst{-1e300, 0};
  for (std::size_t a = 0; a < ps.nMaterial; ++a) {
    const double c = density_[a] / ps.rho[a] - 1;
    if (c > worst.first) worst = {c, a};
  }
  return worst;
}

double defaultSoundSpeed(const ParticleSystem& ps, const Vec3& g) {
  double speed = 0;
  for (std::size_t a = 0; a < ps.nMaterial; ++a) speed = std::max(speed, ps.cloud.U[a].norm());
  const double gn = g.norm();
  if (gn > 0) {
    const Vec3 down = g / gn;
    double lo = 1e300, hi = -1e300;
    for (const auto& x : ps.cloud.positions) {
      lo = std::min(lo, down.dot(x));
      hi = std::max(hi, down.dot(x));
    }
    speed = std::max(speed, std::sqrt(2 * gn * std::max(hi - lo, ps.dx)));
  }
  return 10 * speed;
}

}  // namespace isph
