#include "isph/walls/WallFrictionActiveSet.hpp"

#include <algorithm>

namespace isph {

void WallFrictionActiveSet::start(const WallFriction& friction, const std::vector<Vec3>& u,
                                  const std::vector<label>& origId, std::size_t n) {
  std::vector<double> capacity(n);
  std::vector<Vec3> normal(n);
  for (std::size_t a = 0; a < n; ++a) {
    capacity[a] = friction.capacity(a);
    normal[a] = friction.normal(a);
  }
  start(capacity, normal, friction.slipSpeed(), u, origId);
}

void WallFrictionActiveSet::start(const std::vector<double>& capacity, const std::vector<Vec3>& normal,
                                  double slipSpeed, const std::vector<Vec3>& u, const std::vector<label>& origId) {
  const std::size_t n = capacity.size();
  slipSpeed_ = slipSpeed;
  state_.assign(n, State::free);
  dir_.assign(n, Vec3::Zero());
  stiff_.assign(n, 0.0);
  capacity_.assign(n, 0.0);
  normal_.assign(n, Vec3::Zero());
  for (std::size_t a = 0; a < n; ++a) {
    if (capacity[a] <= 0) continue;
    capacity_[a] = capacity[a];
    normal_[a] = normal[a];
    const auto id = static_cast<std::size_t>(origId[a]);
    if (id < keptState_.size() && keptState_[id] != State::free) {
      state_[a] = keptState_[id];
      stiff_[a] = capacity_[a] / slipSpeed_;
      if (state_[a] == State::stick) continue;
      const Vec3 t = tangential(a, keptDir_[id]);  // the wall may have turned under it
      if (t.norm() > 0.5) {
        dir_[a] = t.normalized();
        continue;
      }
    }
    state_[a] = State::stick;  // new to the wall: classified from u_t
    bool changed = false;
    classify(a, tangential(a, u[a]), changed);
  }
}

void WallFrictionActiveSet::remember(const std::vector<label>& origId) {
  std::size_t size = 0;
  for (std::size_t a = 0; a < state_.size(); ++a) size = std::max(size, static_cast<std::size_t>(origId[a]) + 1);
  std::fill(keptState_.begin(), keptState_.end(), State::free);
  if (keptState_.size() < size) {
    keptState_.resize(size, State::free);
    keptDir_.resize(size, Vec3::Zero());
  }
  for (std::size_t a = 0; a < state_.size(); ++a) {
    const auto id = static_cast<std::size_t>(origId[a]);
    keptState_[id] = state_[a];
    keptDir_[id] = dir_[a];
  }
}

void WallFrictionActiveSet::classify(std::size_t a, const Vec3& ut, bool& changed) {
  const double s = ut.norm();
  if (state_[a] == State::stick) {
    if (s <= slipSpeed_) {
      stiff_[a] = capacity_[a] / slipSpeed_;
      return;
    }
    state_[a] = State::slide;  // the stick force K s would exceed F
    dir_[a] = ut / s;
    stiff_[a] = capacity_[a] / s;
    changed = true;
    return;
  }
  if (ut.dot(dir_[a]) <= slipSpeed_) {  // the Coulomb force reversed the slip, or stopped it
    state_[a] = State::stick;
    stiff_[a] = capacity_[a] / slipSpeed_;
    changed = true;
    return;
  }
  const Vec3 t = ut / s;
  if ((t - dir_[a]).norm() > 0.01) changed = true;  // turned (3D; in 2D t keeps its sign here)
  dir_[a] = t;
  stiff_[a] = capacity_[a] / s;
}

int WallFrictionActiveSet::update(const std::vector<double>& xv, int dim) {
  int changes = 0;
  const auto D = static_cast<std::size_t>(dim);
  for (std::size_t a = 0; a < state_.size(); ++a) {
    if (state_[a] == State::free) continue;
    Vec3 u = Vec3::Zero();
    for (std::size_t d = 0; d < D; ++d) u[static_cast<long>(d)] = xv[a * D + d];
    bool changed = false;
    classify(a, tangential(a, u), changed);
    changes += changed;
  }
  return changes;
}

double WallFrictionActiveSet::block(std::size_t a, int d, int e) const {
  if (state_[a] == State::free) return 0.0;
  const Vec3& n = normal_[a];
  const double p = (d == e ? 1.0 : 0.0) - n[d] * n[e];  // I − n nᵀ
  if (state_[a] == State::stick) return stiff_[a] * p;
  const Vec3& t = dir_[a];
  return stiff_[a] * (p - t[d] * t[e]);  // the lateral stiffness (0 in 2D)
}

Vec3 WallFrictionActiveSet::force(std::size_t a) const {
  return state_[a] == State::slide ? Vec3(-capacity_[a] * dir_[a]) : Vec3(Vec3::Zero());
}

Vec3 WallFrictionActiveSet::applied(std::size_t a, const Vec3& u, int dim) const {
  Vec3 f = force(a);
  if (state_[a] == State::free) return f;
  for (int d = 0; d < dim; ++d) {
    for (int e = 0; e < dim; ++e) f[d] -= block(a, d, e) * u[e];
  }
  return f;
}

}  // namespace isph
