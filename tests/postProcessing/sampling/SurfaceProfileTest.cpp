#include "postProcessing/sampling/SurfaceProfile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/Error.hpp"
#include "postProcessing/sampling/RunOut.hpp"

namespace {

using namespace isph;

void addMaterial(ParticleCloud& c, double x, double y) {
  c.push_back(Vec3(x, y, 0), label(c.size()), Vec3::Zero(), 0, 0, ParticleKind::material, -1, Vec3::Zero(), 0.1);
}

// A staircase on a 0.01 m lattice: column i (centre x = 0.005 + 0.01 i, i = 0..4) holds 5 - i
// particles, so its surface is (5 - i) dx high; plus a wall row under it and a wall particle
// high above column 0 (walls never count).
ParticleCloud staircase() {
  ParticleCloud c;
  c.properties.spacing = 0.01;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5 - i; ++j) addMaterial(c, 0.005 + 0.01 * i, 0.005 + 0.01 * j);
  for (int i = 0; i < 5; ++i)
    c.push_back(Vec3(0.005 + 0.01 * i, -0.005, 0), label(c.size()), Vec3::Zero(), 0, -1, ParticleKind::wall, 0,
                Vec3::UnitY(), 0);
  c.push_back(Vec3(0.005, 0.5, 0), label(c.size()), Vec3::Zero(), 0, -1, ParticleKind::wall, 0, Vec3::UnitY(), 0);
  return c;
}

SurfaceSpec bins(double w, double xMin, double xMax) {
  SurfaceSpec s;
  s.binWidth = w;
  s.xMin = xMin;
  s.xMax = xMax;
  return s;
}

TEST(SurfaceProfile, IsTheHighestMaterialCentrePlusHalfASpacingPerBin) {
  const SurfaceProfile p = surfaceProfile(staircase(), bins(0.01, 0.0, 0.08));
  ASSERT_EQ(p.x.size(), 8u);
  for (int k = 0; k < 8; ++k) {
    EXPECT_NEAR(p.x[k], 0.005 + 0.01 * k, 1e-12);
    EXPECT_EQ(p.filled[k], k < 5) << "bin " << k;
    EXPECT_NEAR(p.height[k], k < 5 ? 0.01 * (5 - k) : 0.0, 1e-12) << "bin " << k;
  }
}

TEST(SurfaceProfile, WideBinsTakeTheHighestColumnAndALastPartialBinIsKept) {
  const SurfaceProfile p = surfaceProfile(staircase(), bins(0.02, 0.0, 0.05));
  ASSERT_EQ(p.x.size(), 3u);  // [0, 0.02), [0.02, 0.04), [0.04, 0.06)
  EXPECT_NEAR(p.height[0], 0.05, 1e-12);
  EXPECT_NEAR(p.height[1], 0.03, 1e-12);
  EXPECT_NEAR(p.height[2], 0.01, 1e-12);
}

TEST(SurfaceProfile, MeasuresAlongAnyDirectionWithHeightNormalToIt) {
  // The staircase seen from x = 0.05 looking back (direction -x): the height axis is then -y,
  // so the origin is put above the staircase, at y = 0.1: heights become 0.1 - y + dx/2.
  SurfaceSpec s = bins(0.01, 0.0, 0.05);
  s.origin = Vec3(0.05, 0.1, 0);
  s.direction = Vec3(-3, 0, 0);
  const SurfaceProfile p = surfaceProfile(staircase(), s);
  // Bin k holds the column at x = 0.045 - 0.01 k (i = 4 - k); its highest "height" is the
  // lowest particle, y = 0.005: 0.1 - 0.005 + 0.005 = 0.1.
  for (int k = 0; k < 5; ++k) EXPECT_NEAR(p.height[k], 0.1, 1e-12) << "bin " << k;
}

TEST(SurfaceProfile, RejectsABadSpec) {
  EXPECT_THROW(surfaceProfile(staircase(), bins(0.0, 0.0, 1.0)), FatalError);
  EXPECT_THROW(surfaceProfile(staircase(), bins(0.01, 1.0, 1.0)), FatalError);
  SurfaceSpec s = bins(0.01, 0.0, 1.0);
  s.direction = Vec3::UnitZ();
  EXPECT_THROW(surfaceProfile(staircase(), s), FatalError);
}

TEST(SurfaceProfile, HeightAtInterpolatesBetweenCentresWithEmptyBinsAtZero) {
  const SurfaceProfile p = surfaceProfile(staircase(), bins(0.01, 0.0, 0.08));
  EXPECT_NEAR(p.heightAt(0.0), 0.05, 1e-12) << "between xMin and the first centre: the first bin";
  EXPECT_NEAR(p.heightAt(0.005), 0.05, 1e-12);
  EXPECT_NEAR(p.heightAt(0.01), 0.045, 1e-12);
  EXPECT_NEAR(p.heightAt(0.0525), 0.0025, 1e-12) << "three quarters of the way to the empty bin";
  EXPECT_NEAR(p.heightAt(0.07), 0.0, 1e-12);
  EXPECT_NEAR(p.heightAt(-0.01), 0.0, 1e-12) << "outside the bins";
  EXPECT_NEAR(p.heightAt(0.5), 0.0, 1e-12);
}

TEST(SurfaceProfile, RmsDistanceToAPolyline) {
  const SurfaceProfile p = surfaceProfile(staircase(), bins(0.01, 0.0, 0.08));
  // On the profile: 0. Each point 2 mm above it: 2 mm. Points of 1 and 3 mm off: sqrt(5) mm.
  EXPECT_NEAR(rmsDistance(p, {{0.005, 0.05}, {0.015, 0.04}, {0.07, 0.0}}), 0.0, 1e-12);
  EXPECT_NEAR(rmsDistance(p, {{0.005, 0.052}, {0.015, 0.042}, {0.07, 0.002}}), 0.002, 1e-12);
  EXPECT_NEAR(rmsDistance(p, {{0.005, 0.049}, {0.06, 0.003}}), std::sqrt(5e-6), 1e-12);
  EXPECT_NEAR(rmsDistance(p, {}), 0.0, 1e-12);
}

TEST(SurfaceProfile, ReadsACsvWithCommentsAndAHeader) {
  const auto file = std::filesystem::temp_directory_path() / "isphSurfaceProfileTest.csv";
  std::ofstream(file) << "# source: somewhere\n# columns: x, y\nx_m,y_m\n0.0,0.1\n 0.2 , 0.05\n\n0.4,0.0\n";
  const auto points = readProfileCsv(file);
  ASSERT_EQ(points.size(), 3u);
  EXPECT_DOUBLE_EQ(points[1].x, 0.2);
  EXPECT_DOUBLE_EQ(points[1].height, 0.05);
  std::ofstream(file) << "x,y\n0.0,0.1\n0.2;oops\n";
  EXPECT_THROW(readProfileCsv(file), FatalError);
  std::filesystem::remove(file);
  EXPECT_THROW(readProfileCsv(file), FatalError);
}

TEST(SurfaceProfile, ToeIsTheRunOutOfTheFarthestParticleWithNeighbours) {
  // The toe of the staircase is the bottom particle of its last column (x = 0.045) plus dx/2; a
  // lone grain splashed ahead at x = 0.2 counts only without the neighbour condition.
  ParticleCloud c = staircase();
  addMaterial(c, 0.2, 0.005);
  RunOutSpec s;
  s.minNeighbours = 2;
  EXPECT_NEAR(*runOut(c, s), 0.05, 1e-12);
  s.minNeighbours = 0;
  EXPECT_NEAR(*runOut(c, s), 0.205, 1e-12);
}

}  // namespace
