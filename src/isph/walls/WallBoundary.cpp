#include "isph/walls/WallBoundary.hpp"

#include <algorithm>

#include "isph/discretisation/MaterialGradient.hpp"
#include "isph/walls/WallBoundaryPressure.hpp"
#include "isph/parallel/GhostExchange.hpp"

namespace isph {

WallBoundary::WallBoundary(ParticleSystem& ps, const MaterialTable& materials, const Vec3& g,
                           double correctionMinDeterminant, bool slidingMaterial)
    : ps_(ps), materials_(materials), g_(g), minDeterminant_(correctionMinDeterminant), slidingMaterial_(slidingMaterial) {}

void WallBoundary::prepare(const std::vector<char>& surface) {
  ps_.wallPullLimit.assign(ps_.size(), 0.0);
  for (std::size_t a = 0; a < ps_.nMaterial; ++a) {
    ps_.wallPullLimit[a] = surface[a] ? 0.0 : std::max(ps_.cloud.p[a], 0.0);
  }
  ps_.wallTangentialGradient.assign(ps_.nMaterial, Vec3::Zero());
  const std::vector<Vec3> gradP =
      slidingMaterial_ ? materialPressureGradient(ps_, minDeterminant_) : std::vector<Vec3>();
  for (std::size_t a = 0; a < ps_.nMaterial; ++a) {
    const bool slides = materials_[static_cast<std::size_t>(ps_.cloud.material[a])].wallContact() ==
                        WallContact::coulombFriction;
    ps_.wallTangentialGradient[a] = slides ? gradP[a] : Vec3(ps_.rho[a] * g_);
  }
  exchangeGhosts(ps_, ps_.wallTangentialGradient);  // parallel: the wall pressure reads it at ghosts
}

void WallBoundary::update(const std::vector<Vec3>& ustar, double dt) { updateWallPressure(ps_, ustar, g_, dt); }

void WallBoundary::settle(const Kernel& kernel, const std::vector<Vec3>& ustar) {
  ps_.neighbours.build(ps_.cloud.positions, kernel, ps_.nMaterial);
  prepare(std::vector<char>(ps_.nMaterial, 0));
  update(ustar, 1.0);
}

}  // namespace isph
