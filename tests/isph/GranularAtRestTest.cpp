// A sand layer at rest on a 20° slope (tutorials/validation/granularAtRest, coarse: 10
// particles over the depth), φ = 30°, base friction 30°: it must stay put for 2 s
// (displacement below dx/4), with the infinite-slope pressure p = ρ |g| cos β × depth
// (L2 within 2 %) and a smooth interior (spread below 1 % of ρ g H) away from the end walls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "CaseRunner.hpp"
#include "particles/CloudIO.hpp"

namespace {

using isph::test::CaseRunner;
using namespace isph;

TEST(GranularAtRest, StaysOnItsSlopeWithLithostaticPressureForTwoSeconds) {
  const double dx = 0.01, rho = 1800, g = 9.81, beta = 20 * M_PI / 180, H = 0.1;
  CaseRunner c("granularAtRest", "granularAtRest");
  c.set("system/particleMeshDict", "spacing", std::to_string(dx));
  c.set("system/controlDict", "writeInterval", "1");
  ASSERT_EQ(c.run(PARTICLEMESH_EXE, "particleMesh"), 0);
  ASSERT_EQ(c.run(SOLVER_EXE, "isphLandslideFoam"), 0) << "see " << c.path() / "log.isphLandslideFoam";
  EXPECT_EQ(c.logValue("isphLandslideFoam", "Wall crossings in the run:"), "0");

  const ParticleCloud start = readCloud(c.path() / "0", "particles");
  const ParticleCloud end = readCloud(c.path() / "2", "particles");
  std::map<label, Vec3> initial;
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (start.kind[i] == 0) initial[start.origId[i]] = start.positions[i];
  }
  double ySurface = 0, maxDisplacement = 0;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (end.kind[i] != 0) continue;
    ySurface = std::max(ySurface, end.positions[i].y());
    maxDisplacement = std::max(maxDisplacement, (end.positions[i] - initial.at(end.origId[i])).norm());
  }
  double sumError2 = 0, sumExact2 = 0, minDev = 1e300, maxDev = -1e300;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (end.kind[i] != 0) continue;
    const double depth = ySurface - end.positions[i].y();
    const double exact = rho * g * std::cos(beta) * depth;
    sumError2 += (end.p[i] - exact) * (end.p[i] - exact);
    sumExact2 += exact * exact;
    const double x = end.positions[i].x();
    if (x > 0.15 && x < 0.45 && depth > 0.1 * H) {
      minDev = std::min(minDev, (end.p[i] - exact) / (rho * g * H));
      maxDev = std::max(maxDev, (end.p[i] - exact) / (rho * g * H));
    }
  }
  const double l2 = std::sqrt(sumError2 / sumExact2);
  std::printf("max displacement %.3g mm (dx/4 = %.3g mm), L2 error of p %.3g%%, interior spread %.3g%%\n",
              1e3 * maxDisplacement, 250 * dx, 100 * l2, 100 * (maxDev - minDev));
  EXPECT_LT(maxDisplacement, 0.25 * dx) << "the layer crept";
  EXPECT_LT(l2, 0.02) << "L2 error of p against rho |g| cos(beta) depth";
  EXPECT_LT(maxDev - minDev, 0.01) << "spread of (p - lithostatic)/(rho g H) in the interior";
}

}  // namespace
