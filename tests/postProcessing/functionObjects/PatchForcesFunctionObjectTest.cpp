// The function objects of controlDict `functions`: patchForces writes the rows of
// sampleForces' table every writeInterval steps into postProcessing/<name>/<startTime>/
// force.dat, scales 2D forces to a width when it has one and says so in the header; an
// unknown type or a bad writeInterval is an error that names the entry.
#include "postProcessing/functionObjects/PatchForcesFunctionObject.hpp"

#include <gtest/gtest.h>

#include "FunctionObjectTestHelpers.hpp"
#include "core/time/Time.hpp"
#include "postProcessing/functionObjects/FunctionObjectList.hpp"

namespace isph {
namespace {

using pptest::TempDir;

using pptest::functionsDict;
const auto rows = pptest::dataRows;

class FunctionObjects : public ::testing::Test {
 protected:
  void SetUp() override {
    pptest::writeText(dir / "system/controlDict",
                      "startFrom startTime; startTime 0; endTime 1; deltaT 0.1; writeInterval 10;\n");
  }
  TempDir dir;
};

// A flat bed of 10 wall particles 0.1 m apart under p = 1000 Pa: 1000 N per metre of width
// pushing into the bed, exactly (sum of p dx); over a width of 0.3 m, 300 N.
TEST_F(FunctionObjects, PatchForcesWritesEveryNStepsPerMetreOrOverTheWidth) {
  Time time(dir.path());
  FunctionObjectList functions(functionsDict("perMetre { type patchForces; patches (bed); }\n"
                                             "wide { type patchForces; patches (bed); width 0.3; writeInterval 2; }"),
                               time);
  ASSERT_EQ(functions.size(), 2u);
  EXPECT_EQ(functions[0].type(), "patchForces");
  const ParticleCloud cloud = pptest::flatBed(10, 0.1, 1000.0);
  for (int step = 0; step < 4; ++step) {
    ++time;
    functions.execute(time, {.cloud = cloud});
  }

  const auto perMetreFile = dir / "postProcessing/perMetre/0/force.dat";
  const auto wideFile = dir / "postProcessing/wide/0/force.dat";
  const auto perMetre = rows(perMetreFile);
  const auto wide = rows(wideFile);
  ASSERT_EQ(perMetre.size(), 4u) << "writeInterval 1: every step";
  ASSERT_EQ(wide.size(), 2u) << "writeInterval 2: steps 2 and 4";
  const int Fn = 3, Fy = 2, nWall = 21;  // 0-based columns of the 2D table (ForceTable.hpp)
  EXPECT_NEAR(perMetre[0][0], 0.1, 1e-12);
  EXPECT_NEAR(wide[0][0], 0.2, 1e-12);
  EXPECT_NEAR(wide[1][0], 0.4, 1e-12);
  for (const auto& r : perMetre) {
    EXPECT_NEAR(r[Fn], 1000.0, 1e-9 * 1000) << "sum p dx per metre";
    EXPECT_NEAR(r[Fy], -1000.0, 1e-9 * 1000);
    EXPECT_EQ(r[nWall], 10);
  }
  for (const auto& r : wide) EXPECT_NEAR(r[Fn], 0.3 * 1000.0, 1e-9 * 300) << "width 0.3 m times the force per metre";

  const std::string perMetreHeader = pptest::readText(perMetreFile);
  const std::string wideHeader = pptest::readText(wideFile);
  EXPECT_NE(perMetreHeader.find("per metre of width"), std::string::npos);
  EXPECT_NE(perMetreHeader.find("# Time [s]\tFx [N/m]\tFy [N/m]\tFn [N/m]"), std::string::npos);
  EXPECT_NE(wideHeader.find("width 0.3 m (forces over the width)"), std::string::npos);
  EXPECT_NE(wideHeader.find("# Time [s]\tFx [N]\tFy [N]\tFn [N]"), std::string::npos);
  EXPECT_NE(wideHeader.find("Mz [N m]"), std::string::npos);
}

// `facing`: the bed's wall particles face +y, so facing (0 1 0) keeps all ten and says so in
// the header, and facing (1 0 0) none of them.
TEST_F(FunctionObjects, FacingKeepsTheFacesThatLookThatWay) {
  Time time(dir.path());
  FunctionObjectList functions(functionsDict("up { type patchForces; patches (bed); facing (0 1 0); }\n"
                                             "side { type patchForces; patches (bed); facing (1 0 0); }"),
                               time);
  const ParticleCloud cloud = pptest::flatBed(10, 0.1, 1000.0);
  ++time;
  functions.execute(time, {.cloud = cloud});
  const auto up = rows(dir / "postProcessing/up/0/force.dat");
  const auto side = rows(dir / "postProcessing/side/0/force.dat");
  const int Fy = 2, nWall = 21;
  ASSERT_EQ(up.size(), 1u);
  ASSERT_EQ(side.size(), 1u);
  EXPECT_NEAR(up[0][Fy], -1000.0, 1e-9 * 1000);
  EXPECT_EQ(up[0][nWall], 10);
  EXPECT_EQ(side[0][nWall], 0);
  EXPECT_EQ(side[0][Fy], 0.0);
  const std::string header = pptest::readText(dir / "postProcessing/up/0/force.dat");
  EXPECT_NE(header.find("patches (bed) (the faces facing (0 1 0))"), std::string::npos) << header;
}

// Beside force.dat, the filtered history (forceFiltered.dat: the same rows, each force column
// filtered over filterWindow) and its figures (forceFigures.txt), written at the end of the run;
// a misspelt filter keyword is an error.
TEST_F(FunctionObjects, PatchForcesWritesTheFilteredHistoryAndItsFigures) {
  Time time(dir.path());
  FunctionObjectList functions(
      functionsDict("bed { type patchForces; patches (bed); filterWindow 0.25; lateForceWindow 0.2; }"), time);
  ParticleCloud cloud = pptest::flatBed(10, 0.1, 1000.0);
  for (int step = 0; step < 5; ++step) {
    for (std::size_t i = 0; i < cloud.size(); ++i) cloud.p[i] = step == 2 ? 3000.0 : 1000.0;  // a spike at 0.3 s
    ++time;
    functions.execute(time, {.cloud = cloud});
  }
  functions.end(time);
  const auto raw = rows(dir / "postProcessing/bed/0/force.dat");
  const auto filtered = rows(dir / "postProcessing/bed/0/forceFiltered.dat");
  const int Fn = 3, nWall = 21;
  ASSERT_EQ(filtered.size(), raw.size());
  ASSERT_EQ(filtered.size(), 5u);
  EXPECT_NEAR(raw[2][Fn], 3000, 1e-9);
  // At 0.3 s the window [0.175, 0.425] holds the whole spike, a triangle of 2000 N/m over
  // [0.2, 0.4] (area 200 N s/m): 1000 + 200 / 0.25.
  EXPECT_NEAR(filtered[2][Fn], 1800, 1e-6);
  EXPECT_EQ(filtered[2][nWall], 10);
  const std::string figures = pptest::readText(dir / "postProcessing/bed/0/forceFigures.txt");
  EXPECT_NE(figures.find("\nfilteredPeak 1800 N/m\n"), std::string::npos) << figures;
  EXPECT_NE(figures.find("\nfilteredPeakTime 0.3 s\n"), std::string::npos) << figures;
  EXPECT_NE(figures.find("\nrawMax 3000 N/m\n"), std::string::npos) << figures;
  EXPECT_NE(figures.find("\nfilterWindow 0.25 s\n"), std::string::npos) << figures;
  EXPECT_NE(figures.find("\nlateForceWindow 0.2 s\n"), std::string::npos) << figures;

  EXPECT_THROW(FunctionObjectList(functionsDict("f { type patchForces; patches (bed); filterWindw 0.02; }"), time),
               FatalError)
      << "a misspelt keyword";
  EXPECT_THROW(FunctionObjectList(functionsDict("f { type patchForces; patches (bed); filterWindow 0; }"), time),
               FatalError);
}

// A run continued from 0.2 s after one that reached 0.4 s: its filtered history and figures
// cover the first run's rows up to 0.2 s and its own after (as keyFigures joins the tables), so
// a peak before the restart is still the peak.
TEST_F(FunctionObjects, AContinuedRunFiltersTheWholeHistory) {
  const std::string entry = "bed { type patchForces; patches (bed); filterWindow 0.01; }";
  ParticleCloud cloud = pptest::flatBed(10, 0.1, 1000.0);
  {
    Time time(dir.path());
    FunctionObjectList functions(functionsDict(entry), time);
    for (int step = 0; step < 4; ++step) {
      for (std::size_t i = 0; i < cloud.size(); ++i) cloud.p[i] = step == 0 ? 5000.0 : 1000.0;  // the peak at 0.1 s
      ++time;
      functions.execute(time, {.cloud = cloud});
    }
    functions.end(time);
  }
  pptest::writeText(dir / "system/controlDict",
                    "startFrom startTime; startTime 0.2; endTime 1; deltaT 0.1; writeInterval 10;\n");
  std::filesystem::create_directories(dir / "0.2");
  Time time(dir.path());
  ASSERT_NEAR(time.value(), 0.2, 1e-12);
  FunctionObjectList functions(functionsDict(entry), time);
  for (std::size_t i = 0; i < cloud.size(); ++i) cloud.p[i] = 2000.0;
  for (int step = 0; step < 2; ++step) {
    ++time;
    functions.execute(time, {.cloud = cloud});
  }
  functions.end(time);
  const auto filtered = rows(dir / "postProcessing/bed/0.2/forceFiltered.dat");
  ASSERT_EQ(filtered.size(), 4u) << "0.1 and 0.2 s of the first run (its 0.3 and 0.4 s replaced), 0.3 and 0.4 s";
  const int Fn = 3;
  EXPECT_NEAR(filtered[0][0], 0.1, 1e-12);
  // A 10 ms window between rows 0.1 s apart: the trace's straight lines around each row; at
  // the first row cut to [0.1, 0.105] (5000 falling to 4800), at 0.3 s from 1950 to 2000 and 2000.
  EXPECT_NEAR(filtered[0][Fn], 4900, 1e-9);
  EXPECT_NEAR(filtered[2][0], 0.3, 1e-12);
  EXPECT_NEAR(filtered[2][Fn], 1987.5, 1e-9);
  const std::string figures = pptest::readText(dir / "postProcessing/bed/0.2/forceFigures.txt");
  EXPECT_NE(figures.find("\nfilteredPeak 4900 N/m\n"), std::string::npos) << figures;
  EXPECT_NE(figures.find("\nfilteredPeakTime 0.1 s\n"), std::string::npos) << figures;
}

TEST_F(FunctionObjects, NoFunctionsIsAnEmptyList) {
  Time time(dir.path());
  EXPECT_EQ(FunctionObjectList(time).size(), 0u);
  ++time;
  EXPECT_FALSE(FunctionObjectList(time).anyDue(time)) << "nothing to compute for an empty list";
}

// anyDue: the solver computes the deviatoric stress only at the steps where some function
// object will read it.
TEST_F(FunctionObjects, AnyDueFollowsTheWriteIntervals) {
  Time time(dir.path());
  FunctionObjectList functions(functionsDict("every3 { type patchForces; patches (bed); writeInterval 3; }\n"
                                             "every2 { type patchForces; patches (bed); writeInterval 2; }"),
                               time);
  std::string due;
  for (int step = 1; step <= 7; ++step) {
    ++time;
    due += functions.anyDue(time) ? '1' : '0';
  }
  EXPECT_EQ(due, "0111010") << "steps 2, 3, 4, 6 (of 1-7)";
}

TEST_F(FunctionObjects, UnknownTypeListsTheAvailableTypes) {
  Time time(dir.path());
  try {
    FunctionObjectList(functionsDict("barrierForce { type forcez; patches (bed); }"), time);
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    const std::string report = e.report();
    EXPECT_NE(report.find("forcez"), std::string::npos) << report;
    EXPECT_NE(report.find("patchForces"), std::string::npos) << report;
    EXPECT_NE(report.find("system/controlDict"), std::string::npos) << report;
    EXPECT_EQ(e.where().line, 2) << report;
  }
}

TEST_F(FunctionObjects, BadEntriesNameTheKeyword) {
  Time time(dir.path());
  for (const std::string& bad : {std::string("f { type patchForces; patches (bed); writeInterval 0; }"),
                                 std::string("f { type patchForces; patches (bed); width -1; }"),
                                 std::string("f { patches (bed); }"), std::string("f 3;")}) {
    EXPECT_THROW(FunctionObjectList(functionsDict(bad), time), FatalError) << bad;
  }
}

}  // namespace
}  // namespace isph
