#include "isph/materials/EquivalentFriction.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace isph {

double equivalentFrictionAngle(double phiCritDegrees, double porePressureRatio) {
  constexpr double deg = std::numbers::pi / 180.0;
  const double mu = std::sin(phiCritDegrees * deg) / (1.0 + porePressureRatio);  // Eq. 12
  return std::asin(mu) / deg;
}

double infiniteSlopePorePressureRatio(const WaterTable& w, double rhoSoil) {
  if (!(w.height >= 0) || !(w.soilDepth > 0) || !(w.rhoWater > 0) || !(rhoSoil > 0)) {
    throw std::invalid_argument("height must be >= 0 and soilDepth, rhoWater and rho positive");
  }
  const double u = w.rhoWater * w.height;  // per g cos²β
  const double sigma = rhoSoil * w.soilDepth;
  if (!(sigma > u)) {
    throw std::invalid_argument("the pore pressure reaches the total stress (rhoWater*height >= rho*soilDepth): "
                                "no effective stress is left");
  }
  return u / (sigma - u);
}

}  // namespace isph
