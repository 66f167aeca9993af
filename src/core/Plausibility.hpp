#pragma once
// Values that are valid but unlikely for a landslide scene, as unit slips make them (phi 0.768
// for 44 degrees in radians, rho 1.379 for 1379 kg/m^3 in g/cm^3, g (0 -98.1 0)): a warning
// with the file and line, not an error (a scaled experiment may need them).
//   friction angles below 5 or above 60 degrees (a wall's 0, frictionless, is deliberate);
//   densities outside 500 to 5,000 kg/m^3;
//   |g| more than 1 % from 9.81 m/s^2.
#include <string>

#include "core/Error.hpp"
#include "core/Types.hpp"

namespace isph {

struct PlausibleRange {
  static constexpr double minFrictionAngle = 5, maxFrictionAngle = 60;  // degrees
  static constexpr double minDensity = 500, maxDensity = 5000;           // kg/m^3
  static constexpr double gravity = 9.81, gravityTolerance = 0.01;      // m/s^2, relative
};

// `what` names the value ("material 'sand': phi", "wall 'bed': frictionAngle").
void warnIfImplausibleFrictionAngle(double degrees, const std::string& what, const SourceLocation& where,
                                    bool zeroAllowed = false);
void warnIfImplausibleDensity(double rho, const std::string& what, const SourceLocation& where);
void warnIfImplausibleGravity(const Vec3& g, const SourceLocation& where);

// The slope that g implies in the x-y plane: the angle of g from -y, in degrees (a bed along x
// in the flume's frame slopes at it; 0 for g = (0 -9.81 0)).
double slopeFromGravity(const Vec3& g);

}  // namespace isph
