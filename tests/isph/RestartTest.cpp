// A run stopped and restarted from its last time directory (startFrom latestTime) matches an
// uninterrupted run: the time directory holds the whole state of the solver (positions, U,
// p, origId, and the time step in its time state; with method wcsph also the densities).
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <thread>

#include "CaseRunner.hpp"
#include "particles/CloudIO.hpp"

namespace {

using isph::test::CaseRunner;
using isph::test::largestDifference;
using namespace isph;

void checkRestart(const std::string& name, const std::string& schemesEntry) {
  const double a = 0.05715, dx = a / 10;
  CaseRunner whole("damBreak", name + "Whole"), split("damBreak", name + "Split");
  for (CaseRunner* c : {&whole, &split}) {
    c->set("system/particleMeshDict", "spacing", std::to_string(dx));
    c->set("system/controlDict", "writeInterval", "0.02");
    if (!schemesEntry.empty()) c->append("system/isphSchemes", schemesEntry);
    ASSERT_EQ(c->run(PARTICLEMESH_EXE, "particleMesh"), 0);
  }
  whole.set("system/controlDict", "endTime", "0.06");
  ASSERT_EQ(whole.run(SOLVER_EXE, "isphLandslideFoam"), 0);
  split.set("system/controlDict", "endTime", "0.04");
  ASSERT_EQ(split.run(SOLVER_EXE, "isphLandslideFoam"), 0);
  split.set("system/controlDict", "endTime", "0.06");
  ASSERT_EQ(split.run(SOLVER_EXE, "isphLandslideFoam.restart"), 0);

  const ParticleCloud A = readCloud(whole.path() / "0.06", "particles");
  const ParticleCloud B = readCloud(split.path() / "0.06", "particles");
  ASSERT_EQ(A.size(), B.size());
  const auto [maxDx, maxDu] = largestDifference(A, B);
  std::printf("largest difference: position %.3g dx, velocity %.3g m/s\n", maxDx / dx, maxDu);
  // The PPE is solved to 1e-8 (relative): differences of that order, amplified over the
  // 0.02 s after the restart, stay far below a thousandth of a spacing. (The explicit method
  // has no solve: its differences are round-off from the reordering of the sums.)
  EXPECT_LT(maxDx, 1e-3 * dx);
  EXPECT_LT(maxDu, 1e-3);
}

TEST(Restart, StoppedAndRestartedRunMatchesAnUninterruptedOne) { checkRestart("restart", ""); }

// The weakly-compressible state includes the densities (of the walls' dynamic boundary
// particles too): without them a restart would start the walls from the extrapolated wall
// pressure and the water from its cut-off p.
TEST(Restart, WeaklyCompressibleRunRestartsFromItsDensities) { checkRestart("restartWcsph", "method wcsph;"); }

// Ctrl-C: the solver writes the time it has reached, logs where to continue, and ends by
// SIGINT (not status 0), so that an Allrun running it stops before its post-processing
// (etc/RunFunctions). The written time is complete: a restart from it runs on.
TEST(Restart, CtrlCWritesTheTimeAndEndsBySigint) {
  const double a = 0.05715;
  CaseRunner c("damBreak", "ctrlC");
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
    const std::string text = isph::test::readText(log);
    std::size_t n = 0;
    for (std::size_t at = text.find("\nTime = "); at != std::string::npos; at = text.find("\nTime = ", at + 1)) ++n;
    return n;
  };
  for (int i = 0; i < 600 && steps() < 20; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_GE(steps(), 20u) << "see " << log;
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  int status = 0;
  pid_t done = 0;
  for (int i = 0; i < 600 && done == 0; ++i) {
    done = ::waitpid(pid, &status, WNOHANG);
    if (done == 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  if (done == 0) ::kill(pid, SIGKILL);
  ASSERT_EQ(done, pid) << "the solver did not stop within a minute of SIGINT; see " << log;
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT)
      << "exit status " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << "; see " << log;

  const std::string stopped = c.logValue("isphLandslideFoam", "Stopped by a signal at time");
  ASSERT_FALSE(stopped.empty()) << "no 'Stopped by a signal at time' line in " << log;
  const std::string timeName = stopped.substr(0, stopped.find(' '));
  const ParticleCloud start = readCloud(c.path() / "0", "particles");
  const ParticleCloud written = readCloud(c.path() / timeName, "particles");
  EXPECT_EQ(written.size(), start.size());

  c.set("system/controlDict", "endTime", std::to_string(std::stod(timeName) + 0.005));
  ASSERT_EQ(c.run(SOLVER_EXE, "isphLandslideFoam.restart"), 0) << "see " << c.path();
  const std::string restartLog = isph::test::readText(c.path() / "log.isphLandslideFoam.restart");
  const auto at = restartLog.rfind("\nTime = ");  // the last step: "Time = t  deltaT = ..."
  ASSERT_NE(at, std::string::npos);
  EXPECT_NEAR(std::stod(restartLog.substr(at + 8)), std::stod(timeName) + 0.005, 1e-9)
      << "the restart did not run on from " << timeName;
}

}  // namespace
