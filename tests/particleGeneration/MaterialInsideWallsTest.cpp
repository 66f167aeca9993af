// checkMaterialInsideWalls (particleGeneration/MaterialInsideWalls.hpp) on the scene of
// tutorials' hydrostaticTank built in code (0.4 m wide, walls 0.5 m high, left and right walls
// first so that they own the bottom corners), at dx 0.025:
//  - the water box inside the tank passes;
//  - a water box 0.05 m across the walls (as the issue measured it: `materialSide left;` on each
//    wall, the advice of auto's tie) keeps sites beside the bottom corners: a FatalError naming
//    the region, the count per patch and a position;
//  - a region above the walls' tops, beside them on their solid side, is past their open ends;
//  - a second region's count is mentioned.
#include "particleGeneration/MaterialInsideWalls.hpp"

#include <gtest/gtest.h>

#include "SceneTestHelpers.hpp"
#include "geometry/Box.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.025;

Scene tank(const Vec2& lo, const Vec2& hi) {
  Scene s = test::emptyScene(dx);
  s.patches = {{"left", 0}, {"right", 0}, {"bottom", 0}};
  test::addRegion(s, "water", std::make_unique<Box>(lo, hi));
  test::addWall(s, "left", {Vec2(0, 0.5), Vec2(0, 0)});
  test::addWall(s, "right", {Vec2(0.4, 0), Vec2(0.4, 0.5)});
  test::addWall(s, "bottom", {Vec2(0, 0), Vec2(0.4, 0)});
  for (label w = 0; w < 3; ++w) {
    s.walls[static_cast<std::size_t>(w)].patch = w;
    s.walls[static_cast<std::size_t>(w)].side = MaterialSide::left;
  }
  return s;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(MaterialInsideWalls, WaterInsideTheTankPasses) {
  const Scene s = tank(Vec2(0, 0), Vec2(0.4, 0.4));
  const GenerationResult r = generateParticles(s);
  EXPECT_NO_THROW(checkMaterialInsideWalls(s, r));
}

TEST(MaterialInsideWalls, ARegionAcrossTheWallsIsAFatalErrorNamingItTheCountPerPatchAndAPosition) {
  const Scene s = tank(Vec2(-0.05, -0.05), Vec2(0.45, 0.4));
  const GenerationResult r = generateParticles(s);
  const std::string m = test::expectFatal([&] { checkMaterialInsideWalls(s, r); }).what();
  // Beside each bottom corner, 2 x 2 sites of the lattice (sites at odd multiples of dx/2).
  EXPECT_TRUE(contains(m, "region 'water' puts 8 of its")) << m;
  EXPECT_TRUE(contains(m, "4 behind patch 'left', 4 behind patch 'right'")) << m;
  EXPECT_TRUE(contains(m, "e.g. at (")) << m;
  EXPECT_TRUE(contains(m, "materialSide")) << m;
}

TEST(MaterialInsideWalls, ARegionBesideTheWallsTopsOnTheirSolidSideIsPastTheirOpenEnds) {
  Scene s = tank(Vec2(0, 0), Vec2(0.4, 0.4));
  test::addRegion(s, "heap", std::make_unique<Box>(Vec2(-0.05, 0.55), Vec2(0.45, 0.6)));
  const GenerationResult r = generateParticles(s);
  const std::string m = test::expectFatal([&] { checkMaterialInsideWalls(s, r); }).what();
  EXPECT_TRUE(contains(m, "region 'heap' puts 8 of its")) << m;
  EXPECT_TRUE(contains(m, "4 past the open end of patch 'left', 4 past the open end of patch 'right'")) << m;
}

}  // namespace
