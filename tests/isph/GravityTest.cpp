// constant/g as the solver reads it (Gravity.hpp), in OpenFOAM's uniformDimensionedVectorField
// form, from a temporary case: the value read (exactly: the decimal digits parse to the nearest
// double); the errors, each naming the file: no constant/g, dimensions that are not those of an
// acceleration (at their line), no value.
#include <gtest/gtest.h>

#include <string>

#include "../postProcessing/PostProcessingTestHelpers.hpp"
#include "core/Error.hpp"
#include "isph/Gravity.hpp"

namespace {

using namespace isph;
using pptest::TempDir;

// constant/g with OpenFOAM's header (lines 1-8), then `body` from line 9.
void writeGravity(const TempDir& dir, const std::string& body) {
  pptest::writeText(dir / "constant/g",
                    "FoamFile\n"
                    "{\n"
                    "    version     2.0;\n"
                    "    format      ascii;\n"
                    "    class       uniformDimensionedVectorField;\n"
                    "    object      g;\n"
                    "}\n"
                    "\n" +
                        body);
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

TEST(Gravity, TheValueOfConstantGIsRead) {
  TempDir dir;
  writeGravity(dir, "dimensions      [0 1 -2 0 0 0 0];\nvalue           (0 -9.81 0);\n");
  EXPECT_EQ(readGravity(dir.path()), Vec3(0, -9.81, 0));
}

TEST(Gravity, ATiltedGravityIsReadComponentByComponent) {
  TempDir dir;
  writeGravity(dir, "dimensions [0 1 -2 0 0 0 0];\nvalue (4.905 -8.4957 0.25);\n");
  EXPECT_EQ(readGravity(dir.path()), Vec3(4.905, -8.4957, 0.25));
}

TEST(Gravity, AMissingFileIsAFatalErrorNamingIt) {
  TempDir dir;
  try {
    readGravity(dir.path());
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_TRUE(contains(m, (dir.path() / "constant" / "g").string())) << m;
  }
}

// [0 1 -1 0 0 0 0] is a velocity: the error is at the dimensions' line (9) of constant/g.
TEST(Gravity, DimensionsOtherThanAnAccelerationAreAFatalErrorAtTheirLine) {
  TempDir dir;
  writeGravity(dir, "dimensions [0 1 -1 0 0 0 0];\nvalue (0 -9.81 0);\n");
  try {
    readGravity(dir.path());
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_TRUE(contains(m, "constant/g") && contains(m, "acceleration") &&
                contains(m, "[0 1 -2 0 0 0 0]"))
        << m;
    ASSERT_TRUE(e.where().file);
    EXPECT_EQ(*e.where().file, (dir.path() / "constant" / "g").string());
    EXPECT_EQ(e.where().line, 9);
  }
}

TEST(Gravity, AMissingValueIsAFatalErrorNamingTheFileAndTheKeyword) {
  TempDir dir;
  writeGravity(dir, "dimensions [0 1 -2 0 0 0 0];\n");
  try {
    readGravity(dir.path());
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_TRUE(contains(m, "'value'")) << m;
    ASSERT_TRUE(e.where().file);
    EXPECT_EQ(*e.where().file, (dir.path() / "constant" / "g").string());
  }
}

// A value of two components: the error is at its line (10).
TEST(Gravity, AValueThatIsNotAVectorIsAFatalErrorAtItsLine) {
  TempDir dir;
  writeGravity(dir, "dimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81);\n");
  try {
    readGravity(dir.path());
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string m = e.what();
    EXPECT_TRUE(contains(m, "value")) << m;
    ASSERT_TRUE(e.where().file);
    EXPECT_EQ(*e.where().file, (dir.path() / "constant" / "g").string());
    EXPECT_EQ(e.where().line, 10);
  }
}

// A slip of a digit warns at the entry (a scaled experiment may mean it: not an error); the log
// says the slope g implies.
TEST(Gravity, ImplausibleMagnitudeWarnsAndTheSlopeIsLogged) {
  TempDir dir;
  writeGravity(dir, "dimensions      [0 1 -2 0 0 0 0];\nvalue           (0 -98.1 0);\n");
  const int before = warningCount();
  testing::internal::CaptureStderr();
  (void)readGravity(dir.path());
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(warningCount(), before + 1);
  EXPECT_TRUE(contains(err, "|g| = 98.1 m/s^2")) << err;
  EXPECT_TRUE(contains(err, "constant/g, line 10")) << err;

  writeGravity(dir, "dimensions      [0 1 -2 0 0 0 0];\nvalue           (8.035854 -5.626776 0);\n");
  testing::internal::CaptureStdout();
  (void)readGravity(dir.path());
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_EQ(warningCount(), before + 1);
  EXPECT_TRUE(contains(out, "--> Note: g = (8.036 -5.627 0) m/s^2, |g| = 9.81 m/s^2: 55.0 deg from -y")) << out;
}

}  // namespace
