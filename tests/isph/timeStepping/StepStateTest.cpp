// The solver's step state round-trips exactly through a time directory (binary and ascii),
// and a damaged one is an error naming its file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/Error.hpp"
#include "isph/timeStepping/StepState.hpp"

namespace isph {
namespace {

namespace fs = std::filesystem;

StepState sample() {
  StepState s;
  s.stepsTaken = 1234;
  s.stepsSinceReorder = 34;
  s.freshStart = true;
  s.viscosityKnown = true;
  s.maxNu = 0.1 / 3;  // not exact in decimal
  s.maxViscousAcceleration = 1.0 / 7;
  s.maxAcceleration = 98.1 / 3;
  s.soundSpeed = 21.000000000000004;
  s.domainMin = Vec3(-0.1, -1.0 / 3, 0);
  s.domainMax = Vec3(2.5, 1e-300, 0);
  s.materialHeights = {0.1 / 3, 2.0 / 3};
  s.frictionStates = {0, 1, 2, 1};
  s.slipDirections = {Vec3::Zero(), Vec3(1.0 / 3, 2.0 / 3, 0), Vec3(0.6, 0.8, 0), Vec3::Zero()};
  s.viscousIncrements = {Vec3(1e-17, 0, 0), Vec3(0, -1.0 / 9, 0)};
  s.viscousIncrementDt = 1e-4 / 3;
  return s;
}

void expectSame(const StepState& a, const StepState& b) {
  EXPECT_EQ(a.stepsTaken, b.stepsTaken);
  EXPECT_EQ(a.stepsSinceReorder, b.stepsSinceReorder);
  EXPECT_EQ(a.freshStart, b.freshStart);
  EXPECT_EQ(a.viscosityKnown, b.viscosityKnown);
  EXPECT_EQ(a.maxNu, b.maxNu);  // bitwise
  EXPECT_EQ(a.maxViscousAcceleration, b.maxViscousAcceleration);
  EXPECT_EQ(a.maxAcceleration, b.maxAcceleration);
  EXPECT_EQ(a.soundSpeed, b.soundSpeed);
  EXPECT_EQ(a.domainMin, b.domainMin);
  EXPECT_EQ(a.domainMax, b.domainMax);
  EXPECT_EQ(a.materialHeights, b.materialHeights);
  EXPECT_EQ(a.frictionStates, b.frictionStates);
  EXPECT_EQ(a.slipDirections, b.slipDirections);
  EXPECT_EQ(a.viscousIncrements, b.viscousIncrements);
  EXPECT_EQ(a.viscousIncrementDt, b.viscousIncrementDt);
}

class StepStateTest : public ::testing::TestWithParam<WriteFormat> {
 protected:
  fs::path dir_ = fs::temp_directory_path() / ("isphStepState_" + std::to_string(::getpid()) + "_" +
                                               std::to_string(static_cast<int>(GetParam())));
  void TearDown() override { fs::remove_all(dir_); }
};

TEST_P(StepStateTest, RoundTripsExactly) {
  EXPECT_FALSE(readStepState(dir_));  // none: a time from particleMesh
  writeStepState(dir_, sample(), GetParam());
  const auto back = readStepState(dir_);
  ASSERT_TRUE(back);
  expectSame(sample(), *back);
}

TEST_P(StepStateTest, ADamagedStateIsAnErrorNamingItsFile) {
  writeStepState(dir_, sample(), GetParam());
  // maxNu's value made nan (a second maxNu would be refused as a key given twice)
  std::ifstream in(dir_ / "uniform" / "isphState");
  std::stringstream text;
  text << in.rdbuf();
  in.close();
  const std::string damaged = std::regex_replace(text.str(), std::regex("\nmaxNu[^;]*;"), "\nmaxNu nan;");
  ASSERT_NE(damaged, text.str());
  std::ofstream(dir_ / "uniform" / "isphState") << damaged;
  try {
    readStepState(dir_);
    ADD_FAILURE() << "no error";
  } catch (const FatalError& e) {
    EXPECT_NE(e.report().find("uniform/isphState"), std::string::npos) << e.report();
    EXPECT_NE(e.report().find("not a finite number"), std::string::npos) << e.report();
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, StepStateTest, ::testing::Values(WriteFormat::ascii, WriteFormat::binary));

}  // namespace
}  // namespace isph
