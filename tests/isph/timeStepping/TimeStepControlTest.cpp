// The adjustable time step (TimeStepControl.hpp): each limit by its formula, the smallest one
// sets the step and is named in the log, and a limit with nothing to limit (no flow, no force,
// no explicit viscosity, no previous step) does not limit. Values of a 1 cm granular run:
// h = 1.3 cm, |u| = 2 m/s, |g| = 9.81 m/s², η/ρ = 0.1 m²/s (a rigid-plastic η bounded at 100 Pa s).
#include "isph/timeStepping/TimeStepControl.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using isph::TimeStepLimits;
using isph::timeStepLimits;

constexpr double h = 0.013, speed = 2.0, maxCo = 0.2, g = 9.81, forceFactor = 0.25, nu = 0.1, viscousFactor = 0.125,
                 maxGrowth = 1.1, maxDeltaT = 1e-2;

TEST(TimeStepControl, EachLimitIsItsFormula) {
  const TimeStepLimits l = timeStepLimits(h, speed, maxCo, g, forceFactor, nu, viscousFactor, 1e-3, maxGrowth, maxDeltaT);
  EXPECT_DOUBLE_EQ(l.courant, maxCo * h / speed);                  // 1.3e-3 s
  EXPECT_DOUBLE_EQ(l.force, forceFactor * std::sqrt(h / g));       // 9.1e-3 s
  EXPECT_DOUBLE_EQ(l.viscous, viscousFactor * h * h / nu);         // 2.1e-4 s
  EXPECT_DOUBLE_EQ(l.growth, maxGrowth * 1e-3);
  EXPECT_DOUBLE_EQ(l.maxDeltaT, maxDeltaT);
  EXPECT_DOUBLE_EQ(l.value(), l.viscous);
  EXPECT_EQ(l.limiting(), "viscous");
}

TEST(TimeStepControl, TheSmallestLimitSetsTheStepAndIsNamed) {
  // Inviscid: the Courant limit; at rest: the force limit; then growth, then maxDeltaT.
  EXPECT_EQ(timeStepLimits(h, speed, maxCo, g, forceFactor, 0, viscousFactor, 0, maxGrowth, maxDeltaT).limiting(),
            "Courant");
  EXPECT_EQ(timeStepLimits(h, 0, maxCo, g, forceFactor, 0, viscousFactor, 0, maxGrowth, maxDeltaT).limiting(), "force");
  EXPECT_EQ(timeStepLimits(h, 0, maxCo, g, forceFactor, 0, viscousFactor, 1e-3, maxGrowth, maxDeltaT).limiting(),
            "growth");
  const TimeStepLimits free = timeStepLimits(h, 0, maxCo, 0, forceFactor, 0, viscousFactor, 0, maxGrowth, maxDeltaT);
  EXPECT_EQ(free.limiting(), "maxDeltaT");
  EXPECT_DOUBLE_EQ(free.value(), maxDeltaT);
}

TEST(TimeStepControl, NothingToLimitDoesNotLimit) {
  const TimeStepLimits l = timeStepLimits(h, 0, maxCo, 0, forceFactor, 0, viscousFactor, 0, maxGrowth, maxDeltaT);
  EXPECT_EQ(l.courant, 1e300) << "no flow";
  EXPECT_EQ(l.force, 1e300) << "no force";
  EXPECT_EQ(l.viscous, 1e300) << "no explicit viscosity (or the implicit step)";
  EXPECT_EQ(l.growth, 1e300) << "the first step";
}

}  // namespace
