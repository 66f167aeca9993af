#include "postProcessing/sampling/WallFilm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/Error.hpp"

// The scenes are built particle by particle, so every figure is exact: the counts are counts,
// and 1e-12 on masses and elevations is the round-off of summing and rotating them (no run, no
// noise to measure). The limits tested (rows thick, angles, speeds) are the definition's own
// (WallFilm.hpp), on either side of each.
namespace {

using namespace isph;

constexpr double dx = 0.01;
constexpr double m = 0.15;  // kg per particle (per metre of width)

// A plane wall through the origin inclined at `degrees` to the horizontal, rising along +x
// (wall particles on its surface every spacing, normal into the material), friction angle
// `delta`, and `rows` rows of material on it, particles k = 0 .. columns - 1 along the wall,
// their centres (r + 1/2) dx from its surface; all at rest unless `speed` is given.
struct Slope {
  Vec3 t, n;
  ParticleCloud cloud;
  label id = 0;

  Slope(double degrees, double delta) {
    const double a = degrees * std::numbers::pi / 180;
    t = Vec3(std::cos(a), std::sin(a), 0);
    n = Vec3(-std::sin(a), std::cos(a), 0);
    cloud.properties.spacing = dx;
    cloud.properties.patches = {{"wall", delta}};
    for (int k = -5; k < 30; ++k) {
      cloud.push_back(k * dx * t, id++, Vec3::Zero(), 0, -1, ParticleKind::wall, 0, n, 0);
    }
  }
  Vec3 site(int k, int r) const { return k * dx * t + (r + 0.5) * dx * n; }
  void addRows(int rows, int firstColumn, int columns, double speed = 0) {
    for (int k = firstColumn; k < firstColumn + columns; ++k)
      for (int r = 0; r < rows; ++r)
        cloud.push_back(site(k, r), id++, speed * t, 0, 0, ParticleKind::material, -1, Vec3::Zero(), m);
  }
};

TEST(WallFilm, AFilmOfOneOrTwoRowsAtRestOnAWallSteeperThanItsFrictionCounts) {
  for (int rows : {1, 2}) {
    Slope s(45, 25);
    s.addRows(rows, 0, 20);
    const WallFilm f = restingWallFilm(s.cloud, WallFilmSpec{});
    EXPECT_EQ(f.particles, 20 * rows) << rows << " rows";
    EXPECT_NEAR(f.mass, 20 * rows * m, 1e-12);
    EXPECT_NEAR(f.lowest, s.site(0, 0).y(), 1e-12);
    EXPECT_NEAR(f.highest, s.site(19, rows - 1).y(), 1e-12);
    EXPECT_EQ(f.resting, 20 * rows);
  }
}

TEST(WallFilm, AWallNoSteeperThanItsFrictionHoldsAFilm) {
  Slope s(20, 25);
  s.addRows(2, 0, 20);
  EXPECT_EQ(restingWallFilm(s.cloud, WallFilmSpec{}).particles, 0);
  Slope level(0, 0);  // a level frictionless floor
  level.addRows(1, 0, 20);
  EXPECT_EQ(restingWallFilm(level.cloud, WallFilmSpec{}).particles, 0);
  Slope tilted(5, 0);  // a frictionless wall that is not level holds nothing
  tilted.addRows(1, 0, 20);
  EXPECT_EQ(restingWallFilm(tilted.cloud, WallFilmSpec{}).particles, 20);
}

TEST(WallFilm, ThickMaterialDoesNotCountAndTheLimitIsTheSpecs) {
  Slope four(45, 25);
  four.addRows(4, 0, 20);
  EXPECT_EQ(restingWallFilm(four.cloud, WallFilmSpec{}).particles, 0);
  Slope three(45, 25);
  three.addRows(3, 0, 20);  // three spacings thick
  EXPECT_EQ(restingWallFilm(three.cloud, WallFilmSpec{}).particles, 0);
  WallFilmSpec thicker;
  thicker.maxThickness = 3.5;
  EXPECT_EQ(restingWallFilm(three.cloud, thicker).particles, 60);
}

// A film running up from a deposit at its foot: the deposit (8 rows over the first 5 columns)
// is carried by itself and does not count; the film above it does, whatever lies beside it.
TEST(WallFilm, OnlyTheFilmAboveADepositCounts) {
  Slope s(45, 25);
  s.addRows(2, 0, 20);
  for (int k = 0; k < 5; ++k)
    for (int r = 2; r < 8; ++r)
      s.cloud.push_back(s.site(k, r), s.id++, Vec3::Zero(), 0, 0, ParticleKind::material, -1, Vec3::Zero(), m);
  const WallFilm f = restingWallFilm(s.cloud, WallFilmSpec{});
  EXPECT_EQ(f.particles, 2 * 15);
  EXPECT_NEAR(f.lowest, s.site(5, 0).y(), 1e-12);
  EXPECT_EQ(f.resting, 2 * 20 + 5 * 6);
}

TEST(WallFilm, MaterialSlidingAboveTheRestSpeedDoesNotCount) {
  Slope s(45, 25);
  s.addRows(2, 0, 20, 0.02);
  WallFilm f = restingWallFilm(s.cloud, WallFilmSpec{});
  EXPECT_EQ(f.particles, 0);
  EXPECT_EQ(f.resting, 0);
  WallFilmSpec slower;
  slower.restSpeed = 0.05;
  f = restingWallFilm(s.cloud, slower);
  EXPECT_EQ(f.particles, 40);
}

// The inclination is taken against gravity, not against y: the same wall under gravity tilted
// by 45 degrees (the flume's frame) is level.
TEST(WallFilm, TheWallsInclinationIsAgainstGravity) {
  Slope s(45, 25);
  s.addRows(2, 0, 20);
  WallFilmSpec tilted;
  tilted.g = -9.81 * s.n;
  EXPECT_EQ(restingWallFilm(s.cloud, tilted).particles, 0);
}

TEST(WallFilm, BadSpecsAreErrors) {
  Slope s(45, 25);
  s.addRows(1, 0, 5);
  WallFilmSpec bad;
  bad.g = Vec3::Zero();
  EXPECT_THROW(restingWallFilm(s.cloud, bad), FatalError);
  bad = WallFilmSpec{};
  bad.restSpeed = 0;
  EXPECT_THROW(restingWallFilm(s.cloud, bad), FatalError);
  bad = WallFilmSpec{};
  bad.maxThickness = -1;
  EXPECT_THROW(restingWallFilm(s.cloud, bad), FatalError);
  s.cloud.properties.spacing = 0;
  EXPECT_THROW(restingWallFilm(s.cloud, WallFilmSpec{}), FatalError);
}

}  // namespace
