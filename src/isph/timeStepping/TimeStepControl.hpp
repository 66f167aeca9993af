#pragma once
// The adjustable time step (numerics.md §6):
//   dt = min( maxCo h/|u|max,  C_f √(h/|f|max),  C_ν ρ h²/η_max (explicit viscosity),
//             growth × dt_previous,  maxDeltaT )
// and which of them set it, for the log.
#include <string>

namespace isph {

struct TimeStepLimits {
  double courant = 1e300;
  double force = 1e300;
  double viscous = 1e300;
  double growth = 1e300;
  double maxDeltaT = 1e300;

  double value() const;
  // "Courant" | "force" | "viscous" | "growth" | "maxDeltaT"
  std::string limiting() const;
};

TimeStepLimits timeStepLimits(double h, double maxSpeed, double maxCo, double maxForce, double forceFactor,
                              double maxKinematicViscosity, double viscousFactor, double previous, double maxGrowth,
                              double maxDeltaT);

}  // namespace isph
