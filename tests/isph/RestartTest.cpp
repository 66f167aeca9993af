// A run stopped and restarted from its last time directory (startFrom latestTime) is bit for
// bit the uninterrupted run: N steps ≡ k steps, restart, N − k steps. The time directory holds
// the whole state of the solver: the particle fields, the time state (uniform/time) and what
// the step carries from one step to the next (uniform/isphState: the reordering counter, the
// stick/slip states at the walls, the scene scales of the viscosity, the limits of the next
// step; StepState.hpp); the AMG hierarchies are built afresh after every write in both
// paths. Compared: every file of the final time directory byte for byte (so every field in
// storage order), and the log of every step after the restart (the time step, every linear
// solve with its iterations and residuals, the Courant number), on the dam break (ISPH and
// WCSPH), the granular layer at rest (in binary and in ascii with 17 digits) and the barrier at
// its -test spacing. Exact: the fields are written in binary, or in ascii with writePrecision
// 17, both of which read back exactly.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <sstream>
#include <thread>

#include "CaseRunner.hpp"
#include "particles/CloudIO.hpp"

namespace {

using isph::test::CaseRunner;
using isph::test::largestDifference;
using isph::test::readText;
using namespace isph;
namespace fs = std::filesystem;

// The relative paths of the files under `dir`, sorted.
std::vector<std::string> filesUnder(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) out.push_back(fs::relative(e.path(), dir).string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The lines of a solver log that say what each step did, from the first step that ends after
// `after`: "Time = ...", the solves, "Co = ..." (not the wall-clock lines).
std::vector<std::string> stepLines(const fs::path& log, double after) {
  std::istringstream in(readText(log));
  std::vector<std::string> out;
  bool on = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("Time = ", 0) == 0) on = std::stod(line.substr(7)) > after + 1e-12;
    if (!on) continue;
    if (line.rfind("Time = ", 0) == 0 || line.find("Solving for") != std::string::npos ||
        line.find("Co = ") != std::string::npos) {
      out.push_back(line);
    }
  }
  return out;
}

// `whole` ran to `end`; `split` to `middle`, then on to `end` from its time directory.
void expectBitIdentical(const CaseRunner& whole, const CaseRunner& split, const std::string& middle,
                        const std::string& end) {
  const fs::path A = whole.path() / end, B = split.path() / end;
  ASSERT_TRUE(fs::is_directory(A) && fs::is_directory(B));
  EXPECT_TRUE(fs::exists(split.path() / middle / "uniform" / "isphState")) << "no solver state written";
  const auto files = filesUnder(A);
  EXPECT_EQ(files, filesUnder(B));
  for (const auto& f : files) {
    EXPECT_TRUE(readText(A / f) == readText(B / f)) << f << " differs between " << A << " and " << B;
  }
  const ParticleCloud a = readCloud(A, "particles"), b = readCloud(B, "particles");
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.origId, b.origId) << "the storage order differs";
  const auto [dx, du] = largestDifference(a, b);  // by origId
  std::printf("largest difference by origId: position %.3g m, velocity %.3g m/s\n", dx, du);
  EXPECT_EQ(dx, 0.0);
  EXPECT_EQ(du, 0.0);
  const auto wholeSteps = stepLines(whole.path() / "log.isphLandslideFoam", std::stod(middle));
  const auto splitSteps = stepLines(split.path() / "log.isphLandslideFoam.restart", std::stod(middle));
  ASSERT_FALSE(wholeSteps.empty());
  EXPECT_EQ(wholeSteps.size(), splitSteps.size());
  for (std::size_t i = 0; i < std::min(wholeSteps.size(), splitSteps.size()); ++i) {
    ASSERT_EQ(wholeSteps[i], splitSteps[i]) << "the first step line that differs after the restart";
  }
}

struct RestartCase {
  std::string tutorial;
  std::vector<std::pair<std::string, std::string>> mesh;     // particleMeshDict edits
  std::vector<std::pair<std::string, std::string>> control;  // controlDict edits
  std::string schemes;                                       // appended to isphSchemes
  std::string middle, end;
  std::string variant = "";  // the tutorial's variant (CaseRunner::useVariant), if any
};

void checkRestart(const std::string& name, const RestartCase& rc) {
  CaseRunner whole(rc.tutorial, name + "Whole"), split(rc.tutorial, name + "Split");
  for (CaseRunner* c : {&whole, &split}) {
    if (!rc.variant.empty()) c->useVariant(rc.variant);
    for (const auto& [k, v] : rc.mesh) c->set("system/particleMeshDict", k, v);
    for (const auto& [k, v] : rc.control) c->set("system/controlDict", k, v);
    if (!rc.schemes.empty()) c->append("system/isphSchemes", rc.schemes);
    ASSERT_EQ(c->run(PARTICLEMESH_EXE, "particleMesh"), 0) << "see " << c->path();
  }
  whole.set("system/controlDict", "endTime", rc.end);
  ASSERT_EQ(whole.run(SOLVER_EXE, "isphLandslideFoam"), 0) << "see " << whole.path();
  split.set("system/controlDict", "endTime", rc.middle);
  ASSERT_EQ(split.run(SOLVER_EXE, "isphLandslideFoam"), 0) << "see " << split.path();
  split.set("system/controlDict", "endTime", rc.end);
  ASSERT_EQ(split.run(SOLVER_EXE, "isphLandslideFoam.restart"), 0) << "see " << split.path();
  expectBitIdentical(whole, split, rc.middle, rc.end);
}

const double a = 0.05715;  // the dam break's column width

// 0.06 s of the dam break at a/10: about 130 steps, two reorderings on either side of the restart.
RestartCase damBreak(const std::string& schemes) {
  return {"damBreak", {{"spacing", std::to_string(a / 10)}}, {{"writeInterval", "0.02"}}, schemes, "0.04", "0.06"};
}

TEST(Restart, DamBreakRestartsBitForBit) { checkRestart("restart", damBreak("")); }

// The weakly-compressible state includes the densities (of the walls' dynamic boundary
// particles too) and the sound speed, which a restart would otherwise take from the heights of
// its own (moved) water.
TEST(Restart, WeaklyCompressibleDamBreakRestartsBitForBit) { checkRestart("restartWcsph", damBreak("method wcsph;")); }

// The layer at rest: Coulomb friction at the bed, whose stick/slip states a restart took
// afresh from the velocities (4 velocity solves in its first step against 1 in the
// uninterrupted run), and the default etaMax from the layer's height (binary, so that the
// restart reads the fields exactly; the tutorial writes ascii with 8 digits for its awk plot).
TEST(Restart, GranularLayerAtRestRestartsBitForBit) {
  checkRestart("restartAtRest", {"granularAtRest",
                                 {{"spacing", "0.01"}},
                                 {{"writeInterval", "0.1"}, {"writeFormat", "binary"}},
                                 "",
                                 "0.2",
                                 "0.3"});
}

// The same layer written in ascii with 17 significant digits, which read back exactly too: a
// user who keeps the tutorials' ascii for their awk scripts can restart bit for bit by raising
// writePrecision (at the tutorials' 8 digits a restart continues from the rounded fields).
TEST(Restart, GranularLayerAtRestWrittenInAsciiWithSeventeenDigitsRestartsBitForBit) {
  checkRestart("restartAtRestAscii", {"granularAtRest",
                                      {{"spacing", "0.01"}},
                                      {{"writeInterval", "0.1"}, {"writeFormat", "ascii"}, {"writePrecision", "17"}},
                                      "",
                                      "0.2",
                                      "0.3"});
}

// Bui et al.'s elastic-plastic model in WCSPH (the column's `-elasticPlastic` variant): its
// state is the deviatoric stress, written as tau, beside the densities.
TEST(Restart, ElasticPlasticColumnRestartsBitForBit) {
  checkRestart("restartElasticPlastic", {"columnCollapse",
                                         {{"spacing", "0.01"}},
                                         {{"writeInterval", "0.05"}, {"writeFormat", "binary"}},
                                         "",
                                         "0.1",
                                         "0.15",
                                         "elasticPlastic"});
}

// The flagship at its -test spacing, through the impact on the barrier (binary, so that the
// restart reads the fields exactly; the tutorial writes ascii for its awk scripts).
TEST(Restart, BarrierRestartsBitForBit) {
  checkRestart("restartBarrier", {"../landslides/barrier",
                                  {{"spacing", "0.0108"}},
                                  {{"writeInterval", "0.1"}, {"writeFormat", "binary"}},
                                  "",
                                  "0.4",
                                  "0.6"});
}

// Ctrl-C: the solver writes the time it has reached, logs where to continue, and ends by
// SIGINT (not status 0), so that an Allrun running it stops before its post-processing
// (etc/RunFunctions). The written time is complete: a restart from it runs on. SIGHUP (the
// terminal closed) does the same and ends by SIGHUP.
void checkStopBySignal(int signal) {
  CaseRunner c("damBreak", "stop" + std::to_string(signal));
  c.set("system/particleMeshDict", "spacing", std::to_string(a / 10));
  c.set("system/controlDict", "endTime", "100");
  c.set("system/controlDict", "writeInterval", "1000");
  ASSERT_EQ(c.run(PARTICLEMESH_EXE, "particleMesh"), 0);

  const auto log = c.path() / "log.isphLandslideFoam";
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(fd, STDOUT_FILENO);
    ::dup2(fd, STDERR_FILENO);
    ::execl(SOLVER_EXE, SOLVER_EXE, "-case", c.path().c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Signal it once it has made 20 steps (at most a minute).
  auto steps = [&] {
    const std::string text = readText(log);
    std::size_t n = 0;
    for (std::size_t at = text.find("\nTime = "); at != std::string::npos; at = text.find("\nTime = ", at + 1)) ++n;
    return n;
  };
  for (int i = 0; i < 600 && steps() < 20; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_GE(steps(), 20u) << "see " << log;
  ASSERT_EQ(::kill(pid, signal), 0);
  int status = 0;
  pid_t done = 0;
  for (int i = 0; i < 600 && done == 0; ++i) {
    done = ::waitpid(pid, &status, WNOHANG);
    if (done == 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (done == 0) ::kill(pid, SIGKILL);
  ASSERT_EQ(done, pid) << "the solver did not stop within a minute of the signal; see " << log;
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal)
      << "exit status " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << "; see " << log;

  const std::string stopped = c.logValue("isphLandslideFoam", "Stopped by a signal at time");
  ASSERT_FALSE(stopped.empty()) << "no 'Stopped by a signal at time' line in " << log;
  const std::string timeName = stopped.substr(0, stopped.find(' '));
  const ParticleCloud start = readCloud(c.path() / "0", "particles");
  const ParticleCloud written = readCloud(c.path() / timeName, "particles");
  EXPECT_EQ(written.size(), start.size());

  c.set("system/controlDict", "endTime", std::to_string(std::stod(timeName) + 0.005));
  ASSERT_EQ(c.run(SOLVER_EXE, "isphLandslideFoam.restart"), 0) << "see " << c.path();
  const std::string restartLog = readText(c.path() / "log.isphLandslideFoam.restart");
  const auto at = restartLog.rfind("\nTime = ");  // the last step: "Time = t  deltaT = ..."
  ASSERT_NE(at, std::string::npos);
  EXPECT_NEAR(std::stod(restartLog.substr(at + 8)), std::stod(timeName) + 0.005, 1e-9)
      << "the restart did not run on from " << timeName;
}

TEST(Restart, CtrlCWritesTheTimeAndEndsBySigint) { checkStopBySignal(SIGINT); }

// SIGHUP exited 129 without writing (issue 34).
TEST(Restart, HangupWritesTheTimeAndEndsBySighup) { checkStopBySignal(SIGHUP); }

}  // namespace
