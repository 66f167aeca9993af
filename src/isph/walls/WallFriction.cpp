#include "isph/walls/WallFriction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "isph/walls/WallBoundaryPressure.hpp"
#include "isph/parallel/GhostExchange.hpp"

namespace isph {

WallFriction::WallFriction(const ParticleSystem& ps, const MaterialTable& materials, const Vec3& gravity,
                           double slipSpeed, FrictionNormal normalStress)
    : slipSpeed_(slipSpeed), gravity_(gravity), normalStress_(normalStress) {
  for (const auto& patch : ps.cloud.properties.patches) {
    tanDelta_.push_back(std::tan(patch.frictionAngle * std::numbers::pi / 180.0));
  }
  bool anyFriction = std::any_of(tanDelta_.begin(), tanDelta_.end(), [](double t) { return t > 0; });
  bool anySlides = false;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    slides_.push_back(materials[i].wallContact() == WallContact::coulombFriction);
    anySlides = anySlides || slides_.back();
  }
  anySlides_ = anySlides;
  active_ = anyFriction && anySlides;
}

void WallFriction::update(const ParticleSystem& ps) {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const std::size_t n = ps.size();
  capacity_.assign(ps.nMaterial, 0.0);
  normal_.assign(ps.nMaterial, Vec3::Zero());
  if (!active_) return;
  const double area = std::pow(ps.dx, ps.dimension - 1);

  // T_w / Σ_c W_cw for every wall particle of a friction patch.
  std::vector<double> share(n, 0.0);
  const long wallEnd = static_cast<long>(ps.dummyBegin());
  const bool hydrostatic = normalStress_ == FrictionNormal::hydrostatic;
#pragma omp parallel for schedule(static)
  for (long iw = static_cast<long>(ps.wallBegin()); iw < wallEnd; ++iw) {
    const auto w = static_cast<std::size_t>(iw);
    const double tanDelta = tanDelta_[static_cast<std::size_t>(c.patch[w])];
    if (tanDelta <= 0 || (!hydrostatic && c.p[w] <= 0)) continue;
    double sum = 0, rhoSum = 0, carried = 0;
    for (long k = nl.start[w]; k < nl.start[w + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto b = static_cast<std::size_t>(nl.index[kk]);
      if (ps.isMaterial(b) && slides_[static_cast<std::size_t>(c.material[b])] && facesMaterial(ps, w, b)) {
        sum += nl.W[kk];
        rhoSum += nl.W[kk] * ps.rho[b];
        if (hydrostatic) carried += nl.W[kk] * std::max(0.0, c.p[b] + ps.rho[b] * gravity_.dot(c.positions[w] - c.positions[b]));
      }
    }
    if (sum <= 0) continue;
    const double pw = hydrostatic ? carried / sum : c.p[w];
    if (pw <= 0) continue;
    // σ_w = p_w + the half layer that p = 0 on the free surface leaves out (the material's
    // weight per area between the surface particles' centres and the real surface).
    const double pressing = std::max(0.0, -gravity_.dot(c.normal[w]));
    const double sigma = pw + 0.5 * (rhoSum / sum) * pressing * ps.dx;
    share[w] = tanDelta * sigma * area / sum;
  }
  exchangeGhosts(ps, share);  // parallel: a ghost wall's share from its whole neighbourhood

  const long nMat = static_cast<long>(ps.nMaterial);
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < nMat; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    if (!slides_[static_cast<std::size_t>(c.material[a])]) continue;
    double F = 0;
    Vec3 normal = Vec3::Zero();
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto w = static_cast<std::size_t>(nl.index[kk]);
      if (!ps.isWall(w) || tanDelta_[static_cast<std::size_t>(c.patch[w])] <= 0 || !facesMaterial(ps, w, a)) continue;
      F += share[w] * nl.W[kk];
      normal += nl.W[kk] * c.normal[w];
    }
    const double len = normal.norm();
    if (F > 0 && len > 0) {
      capacity_[a] = F;
      normal_[a] = normal / len;
    }
  }
}

void WallFriction::applyExplicit(const ParticleSystem& ps, double dt, std::vector<Vec3>& u,
                                 std::vector<Vec3>* applied) const {
  const long nMat = static_cast<long>(ps.nMaterial);
  if (applied) applied->assign(ps.nMaterial, Vec3::Zero());
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < nMat; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    if (capacity_[a] <= 0) continue;
    const Vec3 ut = tangential(a, u[a]);
    const double speed = ut.norm();
    if (speed <= 0) continue;
    const double loss = std::min(dt * capacity_[a] / ps.cloud.mass[a], speed);  // cannot reverse u_t
    u[a] -= loss / speed * ut;
    if (applied) (*applied)[a] = -(ps.cloud.mass[a] * loss / (dt * speed)) * ut;
  }
}

std::vector<Vec3> WallFriction::wallTraction(const ParticleSystem& ps, const std::vector<Vec3>& onMaterial) const {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  std::vector<Vec3> traction(ps.size(), Vec3::Zero());
  if (!active_ || onMaterial.empty()) return traction;
  auto frictionWall = [&](std::size_t w) {
    return ps.isWall(w) && tanDelta_[static_cast<std::size_t>(c.patch[w])] > 0;
  };
  // f_a / Σ_w' W_aw' per material particle, then gathered by each wall particle (no scatter).
  std::vector<Vec3> share(ps.nMaterial, Vec3::Zero());
  const long nMat = static_cast<long>(ps.nMaterial);
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < nMat; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    if (onMaterial[a].squaredNorm() == 0) continue;
    double sum = 0;
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto w = static_cast<std::size_t>(nl.index[kk]);
      if (frictionWall(w) && facesMaterial(ps, w, a)) sum += nl.W[kk];
    }
    if (sum > 0) share[a] = onMaterial[a] / sum;
  }
  exchangeGhosts(ps, share);  // parallel
  const double area = std::pow(ps.dx, ps.dimension - 1);
#pragma omp parallel for schedule(static)
  for (long iw = static_cast<long>(ps.wallBegin()); iw < static_cast<long>(ps.dummyBegin()); ++iw) {
    const auto w = static_cast<std::size_t>(iw);
    if (!frictionWall(w)) continue;
    Vec3 t = Vec3::Zero();
    for (long k = nl.start[w]; k < nl.start[w + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto a = static_cast<std::size_t>(nl.index[kk]);
      if (ps.isMaterial(a) && facesMaterial(ps, w, a)) t -= share[a] * nl.W[kk];
    }
    traction[w] = t / area;
  }
  return traction;
}

}  // namespace isph
