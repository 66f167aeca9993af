// What the solver refuses at start and after every step (StartupChecks.hpp), on a hand-built
// particle system of four material particles and one wall particle (no kernel needed) and on
// temporary cases with a system/controlDict (a Time) and a lagrangian/<cloud> folder:
//  - sceneDomain: the bounding box enlarged each way by its largest side and 10 dx, the same margin
//    in every direction (z too), exact up to rounding;
//  - checkInsideDomain: a material particle outside the domain is a FatalError at its line of the
//    positions file (found by origId: the file is in the order written, the cloud reordered),
//    naming its origId, position and the domain's source; the domain's boundary is inside; wall
//    particles are not checked;
//  - checkStillInDomain: a non-finite position, velocity or pressure, or a particle out of the
//    domain, is a FatalError naming the time, the particle's origId and that the last written
//    time directory is intact;
//  - checkMaterialSideOfWalls: with a bed of wall particles along y = 0, the scene passes; origId 5
//    moved 0.03 m below the bed is a FatalError at its line of the positions file, naming its
//    origId, position, depth and the wall's patch; a particle past the bed's open end is left to
//    the domain check;
//  - checkEndTime: endTime not after the start time (a fresh case, or one resumed at its endTime)
//    is a FatalError at controlDict's endTime line;
//  - checkWriteInterval: a writeInterval shorter than the first step with writeControl runTime or
//    adjustableRunTime is a FatalError at its line; timeStep counts steps and is not checked.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "../postProcessing/PostProcessingTestHelpers.hpp"
#include "core/Error.hpp"
#include "isph/startup/StartupChecks.hpp"

namespace {

using namespace isph;
using pptest::TempDir;

constexpr double dx = 0.01;

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

// Four material particles (origIds 3, 1, 5, 4 in the order of the cloud) spanning
// [0, 0.1] × [0, 0.05], and a wall particle (origId 7) at (0.05, 0, 0). The domain: margin
// 0.1 + 10 dx = 0.2 m, (−0.2 −0.2 −0.2) to (0.3 0.25 0.2).
ParticleSystem scene() {
  ParticleSystem ps;
  auto& c = ps.cloud;
  c.push_back(Vec3(0, 0, 0), 3, Vec3(1, 0, 0), 100, 0, ParticleKind::material, -1, Vec3::Zero(),
              0.2);
  c.push_back(Vec3(0.1, 0.05, 0), 1, Vec3(1, 0, 0), 100, 0, ParticleKind::material, -1,
              Vec3::Zero(), 0.2);
  c.push_back(Vec3(0.02, 0.01, 0), 5, Vec3(1, 0, 0), 100, 0, ParticleKind::material, -1,
              Vec3::Zero(), 0.2);
  c.push_back(Vec3(0.07, 0.04, 0), 4, Vec3(1, 0, 0), 100, 0, ParticleKind::material, -1,
              Vec3::Zero(), 0.2);
  c.push_back(Vec3(0.05, 0, 0), 7, Vec3::Zero(), 0, -1, ParticleKind::wall, 0, Vec3(0, 1, 0), 0);
  ps.dx = dx;
  ps.nMaterial = 4;
  ps.nWall = 1;
  return ps;
}

// The cloud folder as written (wall first, then the material in another order): origId 5, the
// cloud's particle 2, is value 3 of the files, on line 13 of positions.
void writeCloud(const std::filesystem::path& dir) {
  pptest::writeText(
      dir / "positions",
      "FoamFile\n{\n    format ascii;\n    class vectorField;\n    object positions;\n}\n\n"  // 1-7
      "5\n(\n"                                                                                // 8-9
      "(0.05 0 0)\n(0.1 0.05 0)\n(0 0 0)\n(0.02 0.01 0)\n(0.07 0.04 0)\n)\n");  // 10-15
  pptest::writeText(
      dir / "origId",
      "FoamFile\n{\n    format ascii;\n    class labelField;\n    object origId;\n}\n\n"
      "5\n(\n7\n1\n3\n5\n4\n)\n");
}

std::string fatalMessage(const std::function<void()>& f, int* line = nullptr,
                         std::string* file = nullptr) {
  try {
    f();
  } catch (const FatalError& e) {
    if (line) *line = e.where().line;
    if (file && e.where().file) *file = *e.where().file;
    return e.what();
  }
  return "(no FatalError)";
}

void expectVec(const Vec3& actual, const Vec3& expected, const char* what) {
  EXPECT_NEAR((actual - expected).cwiseAbs().maxCoeff(), 0.0, 1e-15)
      << what << ": " << actual.transpose();
}

TEST(StartupChecks, TheDomainIsTheBoundingBoxEnlargedByItsLargestSideAndTenSpacings) {
  const ParticleSystem ps = scene();
  const SceneDomain d = sceneDomain(ps.cloud.positions, dx);
  expectVec(d.min, Vec3(-0.2, -0.2, -0.2), "min");
  expectVec(d.max, Vec3(0.3, 0.25, 0.2), "max");
  // The largest side is y's when the box is tall: 0.3 + 0.1 = 0.4 each way.
  const SceneDomain tall = sceneDomain({Vec3(1, 2, 0), Vec3(1.05, 2.3, 0)}, dx);
  expectVec(tall.min, Vec3(0.6, 1.6, -0.4), "min");
  expectVec(tall.max, Vec3(1.45, 2.7, 0.4), "max");
  const SceneDomain none = sceneDomain({}, dx);
  EXPECT_EQ(none.min, Vec3::Zero());
  EXPECT_EQ(none.max, Vec3::Zero());
}

TEST(StartupChecks, ParticlesInsideTheDomainOrOnItsBoundaryPass) {
  TempDir dir;
  writeCloud(dir / "0/lagrangian/particles");
  ParticleSystem ps = scene();
  const SceneDomain d = sceneDomain(ps.cloud.positions, dx);
  EXPECT_NO_THROW(checkInsideDomain(ps, d, dir / "0/lagrangian/particles", "the first particles"));
  ps.cloud.positions[2] = d.max;
  ps.cloud.positions[3] = d.min;
  EXPECT_NO_THROW(checkInsideDomain(ps, d, dir / "0/lagrangian/particles", "the first particles"));
}

TEST(StartupChecks, AWallParticleOutsideTheDomainIsNotChecked) {
  TempDir dir;
  writeCloud(dir / "0/lagrangian/particles");
  ParticleSystem ps = scene();
  const SceneDomain d = sceneDomain(ps.cloud.positions, dx);
  ps.cloud.positions[4] = Vec3(5, 5, 0);
  EXPECT_NO_THROW(checkInsideDomain(ps, d, dir / "0/lagrangian/particles", "the first particles"));
}

// origId 5 moved to (0.35 0.02 0), 0.05 m beyond the domain's x max.
TEST(StartupChecks, AMaterialParticleOutsideTheDomainIsAFatalErrorAtItsLineOfThePositionsFile) {
  TempDir dir;
  const auto cloudDir = dir / "0.5/lagrangian/particles";
  writeCloud(cloudDir);
  ParticleSystem ps = scene();
  const SceneDomain d = sceneDomain(ps.cloud.positions, dx);
  ps.cloud.positions[2] = Vec3(0.35, 0.02, 0);
  int line = -1;
  std::string file;
  const std::string m = fatalMessage(
      [&] { checkInsideDomain(ps, d, cloudDir, "the bounding box of the first particles"); }, &line,
      &file);
  EXPECT_EQ(file, (cloudDir / "positions").string()) << m;
  EXPECT_EQ(line, 13) << m;
  EXPECT_TRUE(contains(m, "origId 5 (line 13)")) << m;
  EXPECT_TRUE(contains(m, "at (0.35 0.02 0)")) << m;
  EXPECT_TRUE(contains(m, "(-0.2 -0.2 -0.2) to (0.3 0.25 0.2)")) << m;
  EXPECT_TRUE(contains(m, "the bounding box of the first particles")) << m;
}

// The scene with a bed: wall particles (origIds 100...) every dx along y = 0 from x = -0.05 to
// 0.15, patch 'bed'.
ParticleSystem sceneOnABed() {
  ParticleSystem ps = scene();
  ps.cloud.properties.patches = {{"bed", 0.0}};
  for (int i = -5; i <= 15; ++i) {
    if (i == 5) continue;  // (0.05 0 0) is the scene's wall particle
    ps.cloud.push_back(Vec3(i * dx, 0, 0), 100 + i, Vec3::Zero(), 0, -1, ParticleKind::wall, 0, Vec3(0, 1, 0), 0);
  }
  ps.nWall = ps.cloud.size() - ps.nMaterial;
  return ps;
}

TEST(StartupChecks, MaterialOnTheWallsMaterialSidePasses) {
  TempDir dir;
  writeCloud(dir / "0/lagrangian/particles");
  const ParticleSystem ps = sceneOnABed();
  EXPECT_NO_THROW(checkMaterialSideOfWalls(ps, dir / "0/lagrangian/particles"));
  EXPECT_NO_THROW(checkMaterialSideOfWalls(scene(), dir / "0/lagrangian/particles"));  // one wall particle
}

TEST(StartupChecks, AMaterialParticleBehindAWallIsAFatalErrorAtItsLineOfThePositionsFile) {
  TempDir dir;
  const auto cloudDir = dir / "0.5/lagrangian/particles";
  writeCloud(cloudDir);
  ParticleSystem ps = sceneOnABed();
  ps.cloud.positions[2] = Vec3(0.02, -0.03, 0);
  int line = -1;
  std::string file;
  const std::string m = fatalMessage([&] { checkMaterialSideOfWalls(ps, cloudDir); }, &line, &file);
  EXPECT_EQ(file, (cloudDir / "positions").string()) << m;
  EXPECT_EQ(line, 13) << m;
  EXPECT_TRUE(contains(m, "origId 5 (line 13) is at (0.02 -0.03 0), 0.03 m behind wall patch 'bed'")) << m;
  ps.cloud.positions[3] = Vec3(0.05, -0.01, 0);  // a second one: counted
  EXPECT_TRUE(contains(fatalMessage([&] { checkMaterialSideOfWalls(ps, cloudDir); }),
                       "(2 material particles are behind a wall in all)"));
}

TEST(StartupChecks, AMaterialParticlePastAWallsOpenEndIsLeftToTheDomainCheck) {
  TempDir dir;
  writeCloud(dir / "0/lagrangian/particles");
  ParticleSystem ps = sceneOnABed();
  ps.cloud.positions[2] = Vec3(0.3, -0.2, 0);  // fell off the bed's end at x = 0.15
  EXPECT_NO_THROW(checkMaterialSideOfWalls(ps, dir / "0/lagrangian/particles"));
}

// A Time on a temporary case, one step (0.001 s) in.
class StartupChecksInARun : public ::testing::Test {
 protected:
  void SetUp() override {
    pptest::writeText(
        dir / "system/controlDict",
        "startFrom startTime; startTime 0; endTime 1; deltaT 0.001; writeControl timeStep; "
        "writeInterval 100;\n");
  }
  TempDir dir;
  ParticleSystem ps = scene();
  SceneDomain domain = sceneDomain(ps.cloud.positions, dx);
};

TEST_F(StartupChecksInARun, ParticlesStillInTheDomainPass) {
  Time time(dir.path());
  ++time;
  EXPECT_NO_THROW(checkStillInDomain(ps, domain, time));
  ps.cloud.positions[4] = Vec3(5, 5, 0);  // a wall particle is not checked
  EXPECT_NO_THROW(checkStillInDomain(ps, domain, time));
}

TEST_F(StartupChecksInARun,
       ANonFinitePositionVelocityOrPressureIsAFatalErrorNamingTheParticleAndTheTime) {
  Time time(dir.path());
  ++time;
  const double nan = std::numeric_limits<double>::quiet_NaN(),
               inf = std::numeric_limits<double>::infinity();
  for (const int field : {0, 1, 2}) {
    ParticleSystem broken = ps;
    if (field == 0) broken.cloud.positions[2].y() = nan;
    if (field == 1) broken.cloud.U[2].x() = -inf;
    if (field == 2) broken.cloud.p[2] = nan;
    const std::string m = fatalMessage([&] { checkStillInDomain(broken, domain, time); });
    EXPECT_TRUE(contains(m, "diverged at time 0.001")) << "field " << field << ": " << m;
    EXPECT_TRUE(contains(m, "(origId 5)")) << "field " << field << ": " << m;
    EXPECT_TRUE(contains(m, "last written time directory is intact"))
        << "field " << field << ": " << m;
  }
}

// origId 5 at (0.02 −0.25 0), 0.05 m below the domain.
TEST_F(StartupChecksInARun, AParticleThatLeftTheDomainIsAFatalErrorNamingItAndTheTime) {
  Time time(dir.path());
  ++time;
  ps.cloud.positions[2] = Vec3(0.02, -0.25, 0);
  const std::string m = fatalMessage([&] { checkStillInDomain(ps, domain, time); });
  EXPECT_TRUE(contains(m, "(origId 5) left the domain at time 0.001")) << m;
  EXPECT_TRUE(contains(m, "position (0.02 -0.25 0)")) << m;
  EXPECT_TRUE(contains(m, "last written time directory is intact")) << m;
}

// controlDict with endTime on line 4 and writeInterval on line 7.
std::string controlDict(const std::string& startFrom, double endTime,
                        const std::string& writeControl, const std::string& writeInterval) {
  return "startFrom " + startFrom + ";\nstartTime 0;\nstopAt endTime;\nendTime " +
         std::to_string(endTime) + ";\ndeltaT 0.001;\nwriteControl " + writeControl +
         ";\nwriteInterval " + writeInterval + ";\n";
}

TEST(StartupChecks, AnEndTimeAfterTheStartTimePasses) {
  TempDir dir;
  pptest::writeText(dir / "system/controlDict", controlDict("startTime", 0.5, "runTime", "0.1"));
  Time time(dir.path());
  EXPECT_NO_THROW(checkEndTime(time));
}

TEST(StartupChecks, AnEndTimeAtTheStartTimeIsAFatalErrorAtItsLine) {
  TempDir dir;
  pptest::writeText(dir / "system/controlDict", controlDict("startTime", 0, "runTime", "0.1"));
  Time time(dir.path());
  int line = -1;
  std::string file;
  const std::string m = fatalMessage([&] { checkEndTime(time); }, &line, &file);
  EXPECT_TRUE(contains(m, "endTime 0 is not after the start time 0")) << m;
  EXPECT_TRUE(contains(file, "controlDict")) << file;
  EXPECT_EQ(line, 4) << m;
}

// A case resumed from its latest time, 0.5, which is its endTime: no step to make.
TEST(StartupChecks, ACaseResumedAtItsEndTimeIsAFatalErrorAtTheEndTimeLine) {
  TempDir dir;
  pptest::writeText(dir / "system/controlDict", controlDict("latestTime", 0.5, "runTime", "0.1"));
  std::filesystem::create_directories(dir / "0");
  std::filesystem::create_directories(dir / "0.5");
  Time time(dir.path());
  ASSERT_EQ(time.timeName(), "0.5");
  int line = -1;
  const std::string m = fatalMessage([&] { checkEndTime(time); }, &line);
  EXPECT_TRUE(contains(m, "is not after the start time 0.5")) << m;
  EXPECT_TRUE(contains(m, "raise endTime")) << m;
  EXPECT_EQ(line, 4) << m;
}

TEST(StartupChecks, AWriteIntervalShorterThanTheStepIsAFatalErrorAtItsLine) {
  for (const std::string control : {"runTime", "adjustableRunTime"}) {
    TempDir dir;
    pptest::writeText(dir / "system/controlDict", controlDict("startTime", 1, control, "1e-4"));
    Time time(dir.path());
    int line = -1;
    const std::string m = fatalMessage([&] { checkWriteInterval(time, 1e-3); }, &line);
    EXPECT_TRUE(contains(m, "writeInterval 0.0001 s is shorter than the time step 0.001 s"))
        << control << ": " << m;
    EXPECT_TRUE(contains(m, "writeControl " + control)) << m;
    EXPECT_EQ(contains(m, "the step would shrink to 0.0001 s"), control == "adjustableRunTime")
        << m;
    EXPECT_EQ(line, 7) << m;
  }
}

TEST(StartupChecks, AWriteIntervalOfAtLeastTheStepOrInStepsPasses) {
  {
    TempDir dir;
    pptest::writeText(dir / "system/controlDict",
                      controlDict("startTime", 1, "adjustableRunTime", "0.001"));
    Time time(dir.path());
    EXPECT_NO_THROW(checkWriteInterval(time, 1e-3)) << "the interval equal to the step";
  }
  {
    TempDir dir;
    pptest::writeText(dir / "system/controlDict", controlDict("startTime", 1, "timeStep", "1"));
    Time time(dir.path());
    EXPECT_NO_THROW(checkWriteInterval(time, 5))
        << "writeControl timeStep: every step, however long";
  }
}

}  // namespace
