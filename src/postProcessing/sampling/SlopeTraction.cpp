#include "postProcessing/sampling/SlopeTraction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

SlopeTractionError slopeTractionError(const ParticleCloud& cloud, const std::vector<SymmTensor>& tau,
                                      const LithostaticSpec& spec, double phi) {
  if (tau.size() != cloud.size()) {
    fatalError(fmt::format("slope traction: {} values of tau for {} particles", tau.size(), cloud.size()));
  }
  const LithostaticError lith = lithostaticError(cloud, spec);  // checks the spec, finds the surface
  const Vec3 n = spec.normal.normalized();
  const Vec3 gt = spec.g - spec.g.dot(n) * n;
  const double gNormal = -spec.g.dot(n), gShear = gt.norm();
  const double dx = cloud.properties.spacing;
  const double surface = lith.surface + 0.5 * dx;
  const double scale = spec.rho * spec.g.norm() * spec.height;
  const double sinPhi = std::sin(phi * std::numbers::pi / 180.0);
  const auto material = label(ParticleKind::material);

  SlopeTractionError e;
  double errN2 = 0, exactN2 = 0, errT2 = 0, exactT2 = 0;
  double minN = 1e300, maxN = -1e300, minT = 1e300, maxT = -1e300;
  std::size_t count = 0, yielded = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != material) continue;
    ++count;
    const double depth = surface - cloud.positions[i].dot(n);
    const Vec3 traction = dotSymm(tau[i], n) - cloud.p[i] * n;  // σ·n
    const Vec3 exact = spec.rho * depth * spec.g;
    const double errN = -(traction - exact).dot(n);            // σ_nn − ρ|g|cos β d
    const Vec3 errT = (traction - exact) - (traction - exact).dot(n) * n;
    const double signedT = gShear > 0 ? errT.dot(gt / gShear) : 0.0;
    errN2 += errN * errN;
    exactN2 += std::pow(spec.rho * gNormal * depth, 2);
    errT2 += errT.squaredNorm();
    exactT2 += std::pow(spec.rho * gShear * depth, 2);
    const double x = cloud.positions[i].x();
    if (x > spec.xMin && x < spec.xMax && depth - 0.5 * dx > spec.minDepth) {
      minN = std::min(minN, errN / scale);
      maxN = std::max(maxN, errN / scale);
      minT = std::min(minT, signedT / scale);
      maxT = std::max(maxT, signedT / scale);
      ++e.interior;
    }
    if (phi > 0) {
      const double norm = std::sqrt(0.5 * doubleDotSymm(tau[i]));  // |τ| = √(τ:τ/2)
      const double strength = sinPhi * (std::max(cloud.p[i], 0.0) + 0.5 * spec.rho * spec.g.norm() * dx);
      yielded += norm >= 0.99 * strength;
    }
  }
  e.l2Normal = exactN2 > 0 ? std::sqrt(errN2 / exactN2) : std::sqrt(errN2);
  e.l2Shear = exactT2 > 0 ? std::sqrt(errT2 / exactT2) : std::sqrt(errT2);
  e.spreadNormal = e.interior > 0 ? maxN - minN : 0.0;
  e.spreadShear = e.interior > 0 ? maxT - minT : 0.0;
  e.atYield = count > 0 ? static_cast<double>(yielded) / static_cast<double>(count) : 0.0;
  return e;
}

}  // namespace isph
