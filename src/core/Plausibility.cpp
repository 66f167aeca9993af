#include "core/Plausibility.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace isph {

void warnIfImplausibleFrictionAngle(double degrees, const std::string& what, const SourceLocation& where,
                                    bool zeroAllowed) {
  if (zeroAllowed && degrees == 0) return;
  if (degrees >= PlausibleRange::minFrictionAngle && degrees <= PlausibleRange::maxFrictionAngle) return;
  warning(fmt::format("{} {} deg is outside the {} to {} deg of soils and interfaces{}", what, degrees,
                      PlausibleRange::minFrictionAngle, PlausibleRange::maxFrictionAngle,
                      degrees < 1.6 ? fmt::format(" (radians? {} rad is {:.4g} deg)", degrees,
                                                  degrees * 180 / std::numbers::pi)
                                    : std::string()),
          where);
}

void warnIfImplausibleDensity(double rho, const std::string& what, const SourceLocation& where) {
  if (rho >= PlausibleRange::minDensity && rho <= PlausibleRange::maxDensity) return;
  warning(fmt::format("{} {} kg/m^3 is outside the {} to {} kg/m^3 of soils, rock and water{}", what, rho,
                      PlausibleRange::minDensity, PlausibleRange::maxDensity,
                      rho < 10 ? fmt::format(" (g/cm^3? that is {:.6g} kg/m^3)", rho * 1000) : std::string()),
          where);
}

void warnIfImplausibleGravity(const Vec3& g, const SourceLocation& where) {
  const double magnitude = g.norm();
  if (std::abs(magnitude - PlausibleRange::gravity) <= PlausibleRange::gravityTolerance * PlausibleRange::gravity) {
    return;
  }
  warning(fmt::format("|g| = {:.4g} m/s^2 is more than {}% from {} m/s^2 (a scaled experiment? a slip of a "
                      "digit?)",
                      magnitude, 100 * PlausibleRange::gravityTolerance, PlausibleRange::gravity),
          where);
}

double slopeFromGravity(const Vec3& g) { return std::atan2(g.x(), -g.y()) * 180 / std::numbers::pi; }

}  // namespace isph
