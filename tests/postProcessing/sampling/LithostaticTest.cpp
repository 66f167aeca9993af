#include "postProcessing/sampling/Lithostatic.hpp"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "TwentyDegreeLayer.hpp"

namespace {

using namespace isph;

// A 60 x 10 layer of sand (rho 1800) on a 0.01 m lattice, x in (0, 0.6), the top centres at
// y = 0.095, under gravity tilted by 20 degrees, with the exact lithostatic pressure
// rho |g| cos(20 deg) (0.095 - y); plus a wall particle with a wild pressure (never counted).
using namespace isph::test;

ParticleCloud layer() {
  ParticleCloud c;
  c.properties.spacing = 0.01;
  label id = 0;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 10; ++j) {
      const double y = 0.005 + 0.01 * j;
      c.push_back(Vec3(0.005 + 0.01 * i, y, 0), id++, Vec3::Zero(), rho * gMag * std::cos(beta) * (0.095 - y), 0,
                  ParticleKind::material, -1, Vec3::Zero(), 0.18);
    }
  c.push_back(Vec3(0.3, -0.005, 0), id++, Vec3::Zero(), 1e9, -1, ParticleKind::wall, 0, Vec3::UnitY(), 0);
  return c;
}

LithostaticSpec spec() { return twentyDegreeLayerSpec(); }

TEST(LithostaticError, AnExactLithostaticLayerHasNoError) {
  const LithostaticError e = lithostaticError(layer(), spec());
  EXPECT_NEAR(e.surface, 0.095, 1e-12);
  EXPECT_LT(e.l2, 1e-12);
  EXPECT_LT(e.spread, 1e-12);
  EXPECT_EQ(e.interior, 30u * 8u) << "30 columns inside 0.15 < x < 0.45, 8 rows deeper than 0.015 m";
}

TEST(LithostaticError, AScaledPressureGivesItsL2ErrorAndAnInteriorBumpItsSpread) {
  ParticleCloud c = layer();
  for (std::size_t i = 0; i < c.size(); ++i)
    if (c.kind[i] == 0) c.p[i] *= 1.1;
  EXPECT_NEAR(lithostaticError(c, spec()).l2, 0.1, 1e-12);

  c = layer();
  const double bump = 0.01 * rho * gMag * H;  // 1 % of rho |g| H
  c.p[30 * 10 + 4] += bump;                   // x = 0.305, y = 0.045: inside
  c.p[2 * 10 + 4] += 10 * bump;               // x = 0.025: by the end wall, outside the interior
  c.p[30 * 10 + 9] -= 10 * bump;              // the top row: too shallow for the interior
  const LithostaticError e = lithostaticError(c, spec());
  EXPECT_NEAR(e.spread, 0.01, 1e-12);
  EXPECT_GT(e.l2, 0.0);
}

TEST(LithostaticError, DepthIsAlongTheNormalAndGravityItsComponentIntoTheBed) {
  // The same layer turned so that its bed normal is +x: the pressure is unchanged.
  ParticleCloud c = layer();
  for (auto& r : c.positions) r = Vec3(r.y(), -r.x(), 0);
  LithostaticSpec s = spec();
  s.normal = Vec3(2, 0, 0);  // not normalised
  s.g = gMag * Vec3(-std::cos(beta), -std::sin(beta), 0);
  s.xMin = -1e300;
  s.xMax = 1e300;
  EXPECT_LT(lithostaticError(c, s).l2, 1e-12);
}

TEST(LithostaticError, LargestDisplacementMatchesParticlesById) {
  const ParticleCloud start = layer();
  ParticleCloud end = layer();
  end.positions[17] += Vec3(0.003, -0.004, 0);
  end.positions.back() += Vec3(1, 0, 0);  // the wall particle does not count
  std::reverse(end.positions.begin(), end.positions.end());
  std::reverse(end.origId.begin(), end.origId.end());
  std::reverse(end.kind.begin(), end.kind.end());
  EXPECT_NEAR(largestDisplacement(start, end), 0.005, 1e-12);
  EXPECT_EQ(largestDisplacement(start, start), 0.0);
  end.origId[5] = 12345;
  EXPECT_THROW(largestDisplacement(start, end), FatalError);
}

TEST(LithostaticError, BadInputIsAFatalError) {
  LithostaticSpec s = spec();
  s.rho = 0;
  EXPECT_THROW(lithostaticError(layer(), s), FatalError);
  s = spec();
  s.height = -1;
  EXPECT_THROW(lithostaticError(layer(), s), FatalError);
  s = spec();
  s.g = -s.g;  // gravity out of the bed
  EXPECT_THROW(lithostaticError(layer(), s), FatalError);
  s = spec();
  s.xMin = 1.0;
  s.xMax = 2.0;  // nothing inside
  EXPECT_THROW(lithostaticError(layer(), s), FatalError);
  ParticleCloud walls;
  walls.push_back(Vec3(0, 0, 0), 0, Vec3::Zero(), 0, -1, ParticleKind::wall, 0, Vec3::UnitY(), 0);
  EXPECT_THROW(lithostaticError(walls, spec()), FatalError);
}

}  // namespace
