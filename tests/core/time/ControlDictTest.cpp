// Reading system/controlDict run controls, defaults and validation errors.
#include <gtest/gtest.h>

#include "TimeTestHelpers.hpp"
#include "core/time/ControlDict.hpp"

namespace isph {
namespace {

ControlSettings readText(const std::string& text, const std::string& file = "system/controlDict") {
  return ControlSettings::read(Dictionary::parse(text, file));
}

TEST(ControlDict, ReadsEveryKeyword) {
  const auto s = readText(R"(
application     isphFoam;
startFrom       startTime;
startTime       0.5;
stopAt          writeNow;
endTime         2;
deltaT          1e-3;
writeControl    adjustableRunTime;
writeInterval   0.1;
purgeWrite      3;
writeFormat     binary;
writePrecision  8;
timePrecision   7;
adjustTimeStep  yes;
maxCo           0.4;
maxDeltaT       2e-3;
runTimeModifiable false;
)");
  EXPECT_EQ(s.startFrom, StartFrom::startTime);
  EXPECT_DOUBLE_EQ(s.startTime, 0.5);
  EXPECT_EQ(s.stopAt, StopAt::writeNow);
  EXPECT_DOUBLE_EQ(s.endTime, 2);
  EXPECT_DOUBLE_EQ(s.deltaT, 1e-3);
  EXPECT_EQ(s.writeControl, WriteControl::adjustableRunTime);
  EXPECT_DOUBLE_EQ(s.writeInterval, 0.1);
  EXPECT_EQ(s.purgeWrite, 3);
  EXPECT_EQ(s.writeFormat, WriteFormat::binary);
  EXPECT_EQ(s.writePrecision, 8);
  EXPECT_EQ(s.timePrecision, 7);
  EXPECT_TRUE(s.adjustTimeStep);
  EXPECT_DOUBLE_EQ(s.maxCo, 0.4);
  EXPECT_DOUBLE_EQ(s.maxDeltaT, 2e-3);
  EXPECT_FALSE(s.runTimeModifiable);
}

TEST(ControlDict, Defaults) {
  testing::internal::CaptureStdout();
  // A file name of its own: defaults are echoed once per file and keyword in a process.
  static int run = 0;
  const auto s = readText("endTime 1;\ndeltaT 0.01;\nwriteInterval 10;\n",
                          "defaults" + std::to_string(run++) + "/system/controlDict");
  const std::string log = testing::internal::GetCapturedStdout();
  EXPECT_EQ(s.startFrom, StartFrom::latestTime);
  EXPECT_DOUBLE_EQ(s.startTime, 0);
  EXPECT_EQ(s.stopAt, StopAt::endTime);
  EXPECT_EQ(s.writeControl, WriteControl::timeStep);
  EXPECT_EQ(s.purgeWrite, 0);
  EXPECT_EQ(s.writeFormat, WriteFormat::ascii);
  EXPECT_EQ(s.writePrecision, 6);
  EXPECT_EQ(s.timePrecision, 6);
  EXPECT_FALSE(s.adjustTimeStep);
  EXPECT_DOUBLE_EQ(s.maxCo, 1);
  EXPECT_TRUE(s.runTimeModifiable);
  // Every default is echoed (once per process).
  for (const char* key :
       {"startFrom", "stopAt", "writeControl", "purgeWrite", "writeFormat", "writePrecision",
        "timePrecision", "adjustTimeStep", "maxCo", "maxDeltaT", "runTimeModifiable"}) {
    EXPECT_NE(log.find(std::string("default: ") + key + " "), std::string::npos)
        << key << " not echoed in\n"
        << log;
  }
}

TEST(ControlDict, StartTimeRequiredOnlyWithStartFromStartTime) {
  EXPECT_DOUBLE_EQ(
      readText("startFrom latestTime; startTime 3; endTime 1; deltaT 1; writeInterval 1;")
          .startTime,
      3);
  const auto e = test::expectFatal(
      [] { readText("startFrom startTime;\nendTime 1; deltaT 1; writeInterval 1;"); });
  EXPECT_NE(std::string(e.what()).find("startTime"), std::string::npos) << e.report();
}

// The error names the file, the line of the keyword, the keyword and the problem.
void expectInvalid(const std::string& text, int line, const std::string& keyword,
                   const std::string& problem) {
  const auto e = test::expectFatal([&] { readText(text); });
  ASSERT_TRUE(e.where().file) << e.report();
  EXPECT_EQ(*e.where().file, "system/controlDict");
  EXPECT_EQ(e.where().line, line) << e.report();
  const std::string report = e.report();
  EXPECT_NE(report.find("system/controlDict, line " + std::to_string(line)), std::string::npos)
      << report;
  EXPECT_NE(report.find("'" + keyword + "'"), std::string::npos) << report;
  EXPECT_NE(report.find(problem), std::string::npos) << report;
}

const std::string base =
    "startFrom startTime;\nstartTime 1;\nendTime 2;\ndeltaT 0.1;\nwriteInterval 5;\n";

// `base` with the line of `key` commented out (a key given twice is an error), so that the
// entry appended after it stands alone at line 6.
std::string without(const std::string& key) {
  std::string text = base;
  text.insert(text.find("\n" + key + " ") + 1, "// ");
  return text;
}

TEST(ControlDict, ValidationErrors) {
  expectInvalid("startFrom startTime;\nstartTime 3;\nendTime 2;\ndeltaT 0.1;\nwriteInterval 5;\n",
                3, "endTime", "before startTime");
  expectInvalid(without("deltaT") + "deltaT 0;\n", 6, "deltaT", "must be positive");
  expectInvalid(without("deltaT") + "deltaT -1e-3;\n", 6, "deltaT", "must be positive");
  expectInvalid(without("writeInterval") + "writeInterval 0;\n", 6, "writeInterval", "must be positive");
  expectInvalid(without("writeInterval") + "writeInterval 2.5;\n", 6, "writeInterval", "whole number of time steps");
  expectInvalid(base + "purgeWrite -1;\n", 6, "purgeWrite", "0 (keep all) or more");
  expectInvalid(base + "writePrecision 0;\n", 6, "writePrecision", "between 1 and 17");
  expectInvalid(base + "timePrecision 18;\n", 6, "timePrecision", "between 1 and 17");
  expectInvalid(base + "maxCo 0;\n", 6, "maxCo", "must be positive");
  expectInvalid(base + "maxDeltaT -1;\n", 6, "maxDeltaT", "must be positive");
  expectInvalid(base + "stopAt endtime;\n", 6, "stopAt", "did you mean endTime");
  expectInvalid(base + "writeControl clockTime;\n", 6, "writeControl",
                "timeStep|runTime|adjustableRunTime");
  expectInvalid(base + "writeFormat text;\n", 6, "writeFormat", "ascii|binary");
  expectInvalid(base + "timePrecision 6.5;\n", 6, "timePrecision", "an integer");
}

TEST(ControlDict, FractionalWriteIntervalIsFineForRunTime) {
  EXPECT_DOUBLE_EQ(readText(without("writeInterval") + "writeControl runTime;\nwriteInterval 0.25;\n").writeInterval,
                   0.25);
}

}  // namespace
}  // namespace isph
