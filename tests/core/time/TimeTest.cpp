// The run-time controller: start time, write times, endTime, purgeWrite, run-time
// modification of controlDict, restart from uniform/time, signals.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <cstdio>

#include "TimeTestHelpers.hpp"
#include "core/time/StopSignal.hpp"
#include "core/time/Time.hpp"
#include "core/time/TimeName.hpp"

namespace isph {
namespace {

namespace fs = std::filesystem;

void writeControlDict(const test::TempCase& c, const std::string& body) {
  c.write("system/controlDict", body);
}

// Rewrite controlDict with a modification time clearly after the previous one.
void modifyControlDict(const test::TempCase& c, const std::string& body) {
  const fs::path file = c.path() / "system/controlDict";
  const auto before = fs::last_write_time(file);
  writeControlDict(c, body);
  fs::last_write_time(file, before + std::chrono::seconds(10));
}

std::string timeNames(const fs::path& caseDir) {
  std::string out;
  for (const auto& t : listTimes(caseDir)) out += (out.empty() ? "" : " ") + t.name;
  return out;
}

TEST(Time, StartFromLatestFirstAndStartTime) {
  test::TempCase c;
  for (const char* d : {"0", "0.5", "0.25", "constant", ".0.75.tmp.1"}) c.mkdir(d);
  const std::string common = "endTime 1; deltaT 0.01; writeInterval 10;\n";
  writeControlDict(c, "startFrom latestTime;\n" + common);
  Time latest(c.path());
  EXPECT_EQ(latest.timeName(), "0.5");
  EXPECT_DOUBLE_EQ(latest.value(), 0.5);
  EXPECT_DOUBLE_EQ(latest.startTime(), 0.5);
  EXPECT_EQ(latest.timeIndex(), 0);
  EXPECT_EQ(latest.timePath(), c.path() / "0.5");

  writeControlDict(c, "startFrom firstTime;\n" + common);
  EXPECT_EQ(Time(c.path()).timeName(), "0");
  writeControlDict(c, "startFrom startTime; startTime 0.25;\n" + common);
  EXPECT_EQ(Time(c.path()).timeName(), "0.25");

  test::TempCase empty;
  writeControlDict(empty, "startFrom latestTime;\n" + common);
  EXPECT_EQ(Time(empty.path()).timeName(), "0");
}

TEST(Time, AdjustableRunTimeHitsWriteTimesExactly) {
  test::TempCase c;
  writeControlDict(c,
                   "startFrom startTime; startTime 0; endTime 1; deltaT 0.03;\n"
                   "writeControl adjustableRunTime; writeInterval 0.1;\n");
  Time t(c.path());
  std::vector<std::string> written;
  int steps = 0;
  while (t.run()) {
    t.adjustDeltaT(0.03);
    EXPECT_LE(t.deltaT(), 0.03 * (1 + 1e-12));
    ++t;
    ++steps;
    if (t.writeTime()) {
      written.push_back(t.timeName());
      EXPECT_EQ(t.value(), 0.1 * static_cast<double>(written.size())) << t.timeName();
    }
  }
  EXPECT_EQ(written, (std::vector<std::string>{"0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7",
                                               "0.8", "0.9", "1"}));
  EXPECT_EQ(steps, 40);  // 0.1 = 4 steps of 0.025
  EXPECT_EQ(t.value(), 1.0);
}

// A step whose solve failed is redone from its start with half the step: the time, index,
// name, step history and write decision are as if the first attempt had never been made.
TEST(Time, RedoStepTakesBackTheStepAndAdvancesByTheNewOne) {
  test::TempCase c;
  writeControlDict(c,
                   "startFrom startTime; startTime 0; endTime 1; deltaT 0.05;\n"
                   "writeControl adjustableRunTime; writeInterval 0.1;\n");
  Time t(c.path());
  EXPECT_THROW(t.redoStep(0.01), FatalError);  // nothing to redo yet
  t.adjustDeltaT(0.05);
  ++t;  // 0.05
  t.adjustDeltaT(0.05);
  ++t;  // 0.1: a write time
  ASSERT_TRUE(t.writeTime());
  EXPECT_EQ(t.timeIndex(), 2);
  t.redoStep(0.025);
  EXPECT_DOUBLE_EQ(t.value(), 0.075);
  EXPECT_EQ(t.timeName(), "0.075");
  EXPECT_EQ(t.timeIndex(), 2);
  EXPECT_EQ(t.deltaT(), 0.025);
  EXPECT_EQ(t.deltaT0(), 0.05);  // the step before the redone one
  EXPECT_FALSE(t.writeTime()) << "0.075 is not a write time";
  // The run goes on to the write time it missed.
  t.adjustDeltaT(0.05);
  ++t;
  EXPECT_EQ(t.value(), 0.1);
  EXPECT_TRUE(t.writeTime());
  EXPECT_EQ(t.timeIndex(), 3);
}

TEST(Time, TimeStepControlWritesEveryNSteps) {
  test::TempCase c;
  writeControlDict(c,
                   "startFrom startTime; startTime 0; endTime 0.2; deltaT 0.01;\n"
                   "writeControl timeStep; writeInterval 5;\n");
  Time t(c.path());
  std::vector<label> written;
  while (t.run()) {
    ++t;
    if (t.writeTime()) written.push_back(t.timeIndex());
  }
  EXPECT_EQ(written, (std::vector<label>{5, 10, 15, 20}));
  EXPECT_EQ(t.timeName(), "0.2");
}

TEST(Time, EndTimeNeverOvershot) {
  test::TempCase c;
  writeControlDict(c,
                   "startFrom startTime; startTime 0; endTime 1; deltaT 0.03;\n"
                   "writeControl runTime; writeInterval 0.5; maxDeltaT 0.03;\n");
  Time t(c.path());
  std::vector<double> steps;
  while (t.run()) {
    t.adjustDeltaT(0.07);  // clipped to maxDeltaT
    steps.push_back(t.deltaT());
    ++t;
    EXPECT_LE(t.value(), 1.0);
  }
  EXPECT_EQ(t.value(), 1.0);
  EXPECT_TRUE(t.writeTime());
  ASSERT_GE(steps.size(), 3u);
  EXPECT_DOUBLE_EQ(steps.front(), 0.03);
  // 0.96 + 0.04: the last two steps are split evenly rather than leaving a sliver.
  EXPECT_NEAR(steps[steps.size() - 1], 0.02, 1e-12);
  EXPECT_NEAR(steps[steps.size() - 2], 0.02, 1e-12);
}

TEST(Time, RunTimeControlWritesWhenTheIntervalIsCrossed) {
  test::TempCase c;
  writeControlDict(c,
                   "startFrom startTime; startTime 0; endTime 0.3; deltaT 0.01;\n"
                   "writeControl runTime; writeInterval 0.1;\n");
  Time t(c.path());
  std::vector<std::string> written;
  while (t.run()) {
    ++t;
    if (t.writeTime()) written.push_back(t.timeName());
  }
  EXPECT_EQ(written, (std::vector<std::string>{"0.1", "0.2", "0.3"}));
}

TEST(Time, PurgeWriteKeepsTheNewest) {
  test::TempCase c;
  c.mkdir("0");
  writeControlDict(c,
                   "startFrom latestTime; endTime 0.5; deltaT 0.1;\n"
                   "writeControl timeStep; writeInterval 1; purgeWrite 2;\n");
  Time t(c.path());
  while (t.run()) {
    ++t;
    if (t.writeTime()) {
      fs::create_directories(t.timePath());
      t.writeTimeState(t.timePath());
      t.purgeOldWrites();
    }
  }
  EXPECT_EQ(timeNames(c.path()), "0 0.4 0.5");
}

// A rank of a parallel run: the case's controlDict, its processor folder's times (a
// decomposed case), or the case's own when that folder has none (an undecomposed start);
// writes and purges in the processor folder.
TEST(Time, ParallelRunStartsFromItsProcessorFolderOrTheUndecomposedCase) {
  test::TempCase c;
  for (const char* d : {"0", "0.5"}) c.mkdir(d);
  writeControlDict(c,
                   "startFrom latestTime; endTime 0.8; deltaT 0.1;\n"
                   "writeControl timeStep; writeInterval 1; purgeWrite 1;\n");
  {
    Time undecomposed(c.path(), "processor1");
    EXPECT_EQ(undecomposed.timeName(), "0.5");
    EXPECT_FALSE(undecomposed.decomposedStart());
    EXPECT_EQ(undecomposed.startPath(), c.path() / "0.5");
    EXPECT_EQ(undecomposed.timePath(), c.path() / "processor1" / "0.5");
    while (undecomposed.run()) {
      ++undecomposed;
      fs::create_directories(undecomposed.timePath());
      undecomposed.writeTimeState(undecomposed.timePath());
      undecomposed.purgeOldWrites();
    }
  }
  EXPECT_EQ(timeNames(c.path() / "processor1"), "0.8");  // purgeWrite 1, in the processor folder
  EXPECT_EQ(timeNames(c.path()), "0 0.5");
  Time decomposed(c.path(), "processor1");
  EXPECT_EQ(decomposed.timeName(), "0.8");
  EXPECT_TRUE(decomposed.decomposedStart());
  EXPECT_EQ(decomposed.startPath(), c.path() / "processor1" / "0.8");
  EXPECT_EQ(decomposed.timeIndex(), 3);  // from processor1/0.8/uniform/time
  EXPECT_FALSE(decomposed.run());
  EXPECT_EQ(Time(c.path()).startPath(), c.path() / "0.5");
  EXPECT_FALSE(Time(c.path()).decomposedStart());
}

TEST(Time, StopAtWriteNowAtRunTime) {
  test::TempCase c;
  const std::string controls =
      "startFrom startTime; startTime 0; endTime 10; deltaT 0.1;\n"
      "writeControl timeStep; writeInterval 1000;\n";
  writeControlDict(c, controls);
  Time t(c.path());
  for (int k = 0; k < 3; ++k) {
    ASSERT_TRUE(t.run());
    ++t;
    EXPECT_FALSE(t.writeTime());
  }
  modifyControlDict(c, controls + "stopAt writeNow;\n");
  ASSERT_TRUE(t.run());
  testing::internal::CaptureStdout();
  ++t;
  const std::string log = testing::internal::GetCapturedStdout();
  EXPECT_NE(log.find("Re-reading system/controlDict"), std::string::npos) << log;
  EXPECT_TRUE(t.writeTime());
  EXPECT_EQ(t.timeName(), "0.4");
  EXPECT_FALSE(t.run());
}

TEST(Time, StopAtNoWriteNowAtRunTime) {
  test::TempCase c;
  const std::string controls =
      "startFrom startTime; startTime 0; endTime 10; deltaT 0.1;\n"
      "writeControl timeStep; writeInterval 1000;\n";
  writeControlDict(c, controls);
  Time t(c.path());
  ++t;
  modifyControlDict(c, controls + "stopAt noWriteNow;\n");
  ++t;
  EXPECT_FALSE(t.writeTime());
  EXPECT_FALSE(t.run());
}

TEST(Time, EndTimeAndDeltaTChangesAreHonoured) {
  test::TempCase c;
  writeControlDict(
      c, "startFrom startTime; startTime 0; endTime 10; deltaT 0.1; writeInterval 1000;\n");
  Time t(c.path());
  ++t;
  modifyControlDict(
      c, "startFrom startTime; startTime 0; endTime 0.5; deltaT 0.2; writeInterval 1000;\n");
  EXPECT_TRUE(t.readModifiedControlDict());
  EXPECT_FALSE(t.readModifiedControlDict());  // unchanged since
  EXPECT_DOUBLE_EQ(t.endTime(), 0.5);
  EXPECT_DOUBLE_EQ(t.deltaT(), 0.2);
  while (t.run()) ++t;
  EXPECT_EQ(t.timeName(), "0.5");
  EXPECT_TRUE(t.writeTime());
}

TEST(Time, BrokenControlDictAtRunTimeKeepsThePreviousControls) {
  test::TempCase c;
  writeControlDict(
      c, "startFrom startTime; startTime 0; endTime 1; deltaT 0.1; writeInterval 1000;\n");
  Time t(c.path());
  const int warnings = warningCount();
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  modifyControlDict(
      c, "startFrom startTime; startTime 0; endTime 0.5 deltaT 0.2; writeInterval 1000;\n");
  EXPECT_FALSE(t.readModifiedControlDict());
  testing::internal::GetCapturedStdout();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(warningCount(), warnings + 1);
  EXPECT_NE(err.find("previous controls"), std::string::npos) << err;
  EXPECT_DOUBLE_EQ(t.endTime(), 1);
}

TEST(Time, RuntimeModificationOff) {
  test::TempCase c;
  const std::string controls =
      "startFrom startTime; startTime 0; endTime 10; deltaT 0.1; writeInterval 1000;\n"
      "runTimeModifiable false;\n";
  writeControlDict(c, controls);
  Time t(c.path());
  modifyControlDict(c, controls + "stopAt writeNow;\n");
  ++t;
  EXPECT_TRUE(t.run());
}

TEST(Time, WriteTimeStateAndRestart) {
  test::TempCase c;
  writeControlDict(c,
                   "startFrom latestTime; endTime 1; deltaT 0.1; adjustTimeStep yes;\n"
                   "writeControl adjustableRunTime; writeInterval 0.1;\n");
  double writtenValue = 0;
  {
    Time t(c.path());
    t.setDeltaT(1.0 / 3.0 / 10.0);  // three steps of 1/30 to 0.1
    for (int k = 0; k < 4; ++k) {
      t.adjustDeltaT(1.0 / 30.0);
      ++t;
    }
    t.setDeltaT(0.0123);
    ++t;  // an off-grid time whose name is rounded: 0.1 + 1/30 + 0.0123
    ASSERT_EQ(t.timeIndex(), 5);
    fs::create_directories(t.timePath());
    t.writeTimeState(t.timePath());
    writtenValue = t.value();
    EXPECT_EQ(t.timeName(), timeName(writtenValue));
  }
  const std::string name = timeName(writtenValue);
  const Dictionary dict = Dictionary::readFile(c.path() / name / "uniform/time");
  EXPECT_EQ(dict.subDict("FoamFile").get<std::string>("class"), "dictionary");
  EXPECT_EQ(dict.subDict("FoamFile").get<std::string>("location"), name + "/uniform");
  EXPECT_EQ(dict.get<double>("value"), writtenValue);
  EXPECT_EQ(dict.get<std::string>("name"), name);
  EXPECT_EQ(dict.get<label>("index"), 5);
  EXPECT_DOUBLE_EQ(dict.get<double>("deltaT"), 0.0123);
  EXPECT_NEAR(dict.get<double>("deltaT0"), 1.0 / 30.0, 1e-12);

  Time restart(c.path());
  EXPECT_EQ(restart.timeName(), name);
  EXPECT_EQ(restart.value(), writtenValue);  // exact, not the rounded name
  EXPECT_EQ(restart.timeIndex(), 5);
  EXPECT_DOUBLE_EQ(restart.deltaT(), 0.0123);
  ++restart;
  EXPECT_EQ(restart.timeIndex(), 6);
}

// A restart (after Ctrl-C at an odd time) writes on the grid of the run it continues: the same
// sums origin + k writeInterval, so that a restart steps as the uninterrupted run. A changed
// writeInterval starts a grid at the restart.
TEST(Time, RestartContinuesTheWriteGrid) {
  test::TempCase c;
  const std::string controls =
      "startFrom latestTime; endTime 0.5; deltaT 0.03; writeControl adjustableRunTime; writeInterval ";
  writeControlDict(c, controls + "0.1;\n");
  std::vector<double> continuous;
  {
    Time t(c.path());
    while (t.run()) {
      t.adjustDeltaT(0.03);
      ++t;
      if (t.writeTime()) continuous.push_back(t.value());
      if (t.timeIndex() == 6) {  // stopped here (0.15)
        fs::create_directories(t.timePath());
        t.writeTimeState(t.timePath());
      }
    }
  }
  ASSERT_EQ(continuous.size(), 5u);
  std::vector<double> restarted;
  Time restart(c.path());
  EXPECT_EQ(restart.timeName(), "0.15");
  while (restart.run()) {
    restart.adjustDeltaT(0.03);
    ++restart;
    if (restart.writeTime()) restarted.push_back(restart.value());
  }
  EXPECT_EQ(restarted, std::vector<double>(continuous.begin() + 1, continuous.end()));  // bitwise

  writeControlDict(c, controls + "0.2;\n");
  Time changed(c.path());  // latestTime: 0.15 still (nothing else was written)
  changed.adjustDeltaT(0.5);
  EXPECT_NEAR(changed.deltaT(), 0.2, 1e-12);  // the next write at 0.15 + 0.2
}

TEST(Time, RestartWithoutAdjustTimeStepUsesControlDictDeltaT) {
  test::TempCase c;
  c.write("0.5/uniform/time", "value 0.5; name \"0.5\"; index 50; deltaT 0.02; deltaT0 0.02;\n");
  writeControlDict(c, "startFrom latestTime; endTime 1; deltaT 0.01; writeInterval 10;\n");
  Time t(c.path());
  EXPECT_EQ(t.timeIndex(), 50);
  EXPECT_DOUBLE_EQ(t.deltaT(), 0.01);
}

TEST(Time, TimePrecisionGrowsWhenNamesWouldCollide) {
  test::TempCase c;
  c.mkdir("1");
  writeControlDict(c, "startFrom latestTime; endTime 2; deltaT 1e-7; writeInterval 1;\n");
  Time t(c.path());
  const int warnings = warningCount();
  testing::internal::CaptureStderr();
  ++t;
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(t.timeName(), "1.0000001");
  EXPECT_EQ(t.timePrecision(), 8);
  EXPECT_EQ(warningCount(), warnings + 1);
  EXPECT_NE(err.find("timePrecision from 6 to 8"), std::string::npos) << err;
}

TEST(Time, MisspeltKeywordIsAnErrorOthersAccepted) {
  test::TempCase c;
  writeControlDict(c,
                   "application isphFoam; libs (); functions { probes { type probes; } }\n"
                   "endTime 1; deltaT 0.1; writeInterval 1; writeIntervall 2;\n");
  try {
    Time t(c.path());
    ADD_FAILURE() << "writeIntervall accepted";
  } catch (const FatalError& e) {
    EXPECT_NE(e.report().find("writeIntervall"), std::string::npos) << e.report();
    EXPECT_NE(e.report().find("did you mean writeInterval"), std::string::npos) << e.report();
  }
  writeControlDict(c,
                   "application isphFoam; libs (); functions { probes { type probes; } }\n"
                   "endTime 1; deltaT 0.1; writeInterval 1; remark none;\n");
  const int warnings = warningCount();
  testing::internal::CaptureStderr();
  Time t(c.path());
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(warningCount(), warnings + 1);
  EXPECT_NE(err.find("unknown keyword 'remark'"), std::string::npos) << err;
  EXPECT_TRUE(t.controlDict().isDict("functions"));
}

TEST(Time, ExecutionTimeLine) {
  test::TempCase c;
  writeControlDict(c, "endTime 1; deltaT 0.1; writeInterval 1;\n");
  const Time t(c.path());
  const std::string line = t.executionTimeLine();
  double cpu = -1;
  int clock = -1;
  char extra = 0;
  EXPECT_EQ(std::sscanf(line.c_str(), "ExecutionTime = %lf s  ClockTime = %d s%c", &cpu, &clock, &extra), 2)
      << line;
  EXPECT_GE(cpu, 0.0);
  EXPECT_GE(clock, 0);
}

TEST(TimeDeathTest, FirstSignalWritesAndStops) {
  test::TempCase c;
  writeControlDict(
      c, "startFrom startTime; startTime 0; endTime 10; deltaT 0.1; writeInterval 1000;\n");
  EXPECT_EXIT(
      {
        Time t(c.path());
        stopSignal::install();
        ++t;
        const bool before = !t.writeTime() && t.run() && !stopSignal::caught();
        std::raise(SIGTERM);
        ++t;
        std::exit(before && stopSignal::caught() == SIGTERM && t.writeTime() && !t.run() &&
                          t.timeName() == "0.2"
                      ? 0
                      : 1);
      },
      testing::ExitedWithCode(0), "Signal caught");
}

}  // namespace
}  // namespace isph
