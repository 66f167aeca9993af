#include "isph/timeStepping/TimeStepControl.hpp"

#include <algorithm>
#include <cmath>

namespace isph {

double TimeStepLimits::value() const { return std::min({courant, force, viscous, growth, maxDeltaT}); }

std::string TimeStepLimits::limiting() const {
  const double v = value();
  if (v == courant) return "Courant";
  if (v == force) return "force";
  if (v == viscous) return "viscous";
  if (v == growth) return "growth";
  return "maxDeltaT";
}

TimeStepLimits timeStepLimits(double h, double maxSpeed, double maxCo, double maxForce, double forceFactor,
                              double maxKinematicViscosity, double viscousFactor, double previous, double maxGrowth,
                              double maxDeltaT) {
  TimeStepLimits l;
  if (maxSpeed > 0) l.courant = maxCo * h / maxSpeed;
  if (maxForce > 0) l.force = forceFactor * std::sqrt(h / maxForce);
  if (maxKinematicViscosity > 0) l.viscous = viscousFactor * h * h / maxKinematicViscosity;
  if (previous > 0) l.growth = maxGrowth * previous;
  l.maxDeltaT = maxDeltaT;
  return l;
}

}  // namespace isph
