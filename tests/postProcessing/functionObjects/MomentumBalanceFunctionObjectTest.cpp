// The function object momentumBalance: F = M g − dP/dt over the material particles (walls and
// dummies left out), the mean over the interval between two executions, no row for the
// first, per metre or over a width, and its errors.
#include "postProcessing/functionObjects/MomentumBalanceFunctionObject.hpp"

#include <gtest/gtest.h>

#include "FunctionObjectTestHelpers.hpp"
#include "core/time/Time.hpp"
#include "postProcessing/functionObjects/FunctionObjectList.hpp"

namespace isph {
namespace {

using pptest::TempDir;

using pptest::functionsDict;
const auto rows = pptest::dataRows;

// Ten material particles of 1 kg/m each over a bed whose walls and dummies are given a mass
// too (they must not count); all move at (1, 0) m/s.
ParticleCloud scene() {
  ParticleCloud c = pptest::flatBed(10, 0.1, 1000.0);
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] != static_cast<label>(ParticleKind::material)) c.mass[i] = 5.0;
  }
  return c;
}

void setMaterialVelocity(ParticleCloud& c, const Vec3& u) {
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] == static_cast<label>(ParticleKind::material)) c.U[i] = u;
  }
}

class MomentumBalance : public ::testing::Test {
 protected:
  void SetUp() override {
    pptest::writeText(dir / "system/controlDict",
                      "startFrom startTime; startTime 0; endTime 1; deltaT 0.1; writeInterval 10;\n");
  }
  TempDir dir;
  const Vec3 g{0, -9.81, 0};
};

// Between t = 0.1 and 0.2 s the material's velocity goes from (1, 0) to (1.5, -0.2) m/s:
// dP/dt = 10 kg/m (0.5, -0.2) m/s / 0.1 s = (50, -20) N/m, W = (0, -98.1) N/m, so the
// material pushes on its walls with F = W - dP/dt = (-50, -78.1) N/m; 0.3 times that over
// 0.3 m. Then at rest (t = 0.3 s, U back to 0): dP/dt = 10 (-1.5, 0.2) / 0.1.
TEST_F(MomentumBalance, TheForceOnTheWallsIsTheWeightLessTheRateOfMomentum) {
  Time time(dir.path());
  FunctionObjectList functions(functionsDict("perMetre { type momentumBalance; }\n"
                                             "wide { type momentumBalance; width 0.3; }"),
                               time);
  ParticleCloud c = scene();
  ++time;
  functions.execute(time, {.cloud = c, .gravity = &g});
  setMaterialVelocity(c, Vec3(1.5, -0.2, 0));
  ++time;
  functions.execute(time, {.cloud = c, .gravity = &g});
  setMaterialVelocity(c, Vec3::Zero());
  ++time;
  functions.execute(time, {.cloud = c, .gravity = &g});

  const auto perMetre = rows(dir / "postProcessing/perMetre/0/momentum.dat");
  const auto wide = rows(dir / "postProcessing/wide/0/momentum.dat");
  ASSERT_EQ(perMetre.size(), 2u) << "no row for the first execution: it has no earlier momentum";
  ASSERT_EQ(wide.size(), 2u);
  // Time M Px Py dPx/dt dPy/dt Wx Wy Fx Fy
  const std::vector<double> expected0 = {0.2, 10, 15, -2, 50, -20, 0, -98.1, -50, -78.1};
  const std::vector<double> expected1 = {0.3, 10, 0, 0, -150, 20, 0, -98.1, 150, -118.1};
  ASSERT_EQ(perMetre[0].size(), expected0.size());
  for (std::size_t k = 0; k < expected0.size(); ++k) {
    EXPECT_NEAR(perMetre[0][k], expected0[k], 1e-9 * (1 + std::abs(expected0[k]))) << "column " << k;
    EXPECT_NEAR(perMetre[1][k], expected1[k], 1e-9 * (1 + std::abs(expected1[k]))) << "column " << k;
    const double s = k == 0 ? 1.0 : 0.3;  // every column but the time scales with the width
    EXPECT_NEAR(wide[0][k], s * expected0[k], 1e-9 * (1 + std::abs(expected0[k]))) << "column " << k;
  }

  const std::string header = pptest::readText(dir / "postProcessing/perMetre/0/momentum.dat");
  EXPECT_NE(header.find("per metre of width"), std::string::npos) << header;
  EXPECT_NE(header.find("# Time [s]\tM [kg/m]\tPx [kg m/s/m]\tPy [kg m/s/m]\tdPx/dt [N/m]\tdPy/dt [N/m]\tWx [N/m]\tWy "
                        "[N/m]\tFx [N/m]\tFy [N/m]"),
            std::string::npos)
      << header;
  const std::string wideHeader = pptest::readText(dir / "postProcessing/wide/0/momentum.dat");
  EXPECT_NE(wideHeader.find("over a width of 0.3 m"), std::string::npos) << wideHeader;
  EXPECT_NE(wideHeader.find("\tFy [N]"), std::string::npos) << wideHeader;
}

// writeInterval 2: rows at steps 4 and 6, each the mean rate over its two steps.
TEST_F(MomentumBalance, TheRateIsTheMeanOverTheWriteInterval) {
  Time time(dir.path());
  FunctionObjectList functions(functionsDict("every2 { type momentumBalance; writeInterval 2; }"), time);
  ParticleCloud c = scene();
  for (int step = 1; step <= 6; ++step) {
    ++time;
    setMaterialVelocity(c, Vec3(0.1 * step, 0, 0));  // dU/dt = 1 m/s², so dP/dt = 10 N/m
    functions.execute(time, {.cloud = c, .gravity = &g});
  }
  const auto r = rows(dir / "postProcessing/every2/0/momentum.dat");
  ASSERT_EQ(r.size(), 2u) << "steps 2 (recorded), 4 and 6";
  for (const auto& row : r) {
    EXPECT_NEAR(row[4], 10.0, 1e-9);
    EXPECT_NEAR(row[8], -10.0, 1e-9) << "Fx = Wx - dPx/dt";
  }
  EXPECT_NEAR(r[0][0], 0.4, 1e-12);
  EXPECT_NEAR(r[1][0], 0.6, 1e-12);
}

TEST_F(MomentumBalance, BadEntriesAndAMissingGravityAreErrors) {
  Time time(dir.path());
  EXPECT_THROW(FunctionObjectList(functionsDict("f { type momentumBalance; width 0; }"), time), FatalError);
  FunctionObjectList functions(functionsDict("f { type momentumBalance; }"), time);
  const ParticleCloud c = scene();
  ++time;
  try {
    functions.execute(time, {.cloud = c});
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    EXPECT_NE(e.report().find("gravity"), std::string::npos) << e.report();
    EXPECT_NE(e.report().find("'f'"), std::string::npos) << e.report();
  }
}

}  // namespace
}  // namespace isph
