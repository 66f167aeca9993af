// The case lock (issue 54): one writer of time directories per case. A second is refused naming
// the holder, a lock whose process has ended is taken over with a line saying so, another host's
// is refused with the way out, and the holder removes it at its end.
#include "core/io/CaseLock.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/Error.hpp"
#include "core/io/ReadFile.hpp"
#include "core/io/StagingNames.hpp"

namespace {

using namespace isph;
namespace fs = std::filesystem;

struct Case {
  fs::path dir = fs::temp_directory_path() / ("isphCaseLock-" + std::to_string(::getpid()));
  Case() { fs::remove_all(dir), fs::create_directories(dir); }
  ~Case() { fs::remove_all(dir); }
  fs::path lock() const { return dir / CaseLock::fileName; }
};

// The message of the FatalError with which a lock for `command` on `dir` is refused; empty when
// it is taken.
std::string refusal(const fs::path& dir, const std::string& command) {
  std::string taken;
  try {
    const CaseLock lock(dir, command, taken);
  } catch (const FatalError& e) {
    return e.what();
  }
  return {};
}

// The pid of a process that has ended (a child, reaped).
long endedPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return static_cast<long>(child);
}

TEST(CaseLock, HoldsWhoAndRefusesASecondWriter) {
  Case c;
  std::string taken;
  {
    const CaseLock first(c.dir, "isphLandslideFoam -case x", taken);
    EXPECT_TRUE(taken.empty());
    const std::string text = readFileBytes(c.lock());
    EXPECT_NE(text.find("pid          " + std::to_string(::getpid()) + "\n"), std::string::npos) << text;
    EXPECT_NE(text.find("host         " + thisHost() + "\n"), std::string::npos) << text;
    EXPECT_NE(text.find("started      "), std::string::npos) << text;
    EXPECT_NE(text.find("command      isphLandslideFoam -case x\n"), std::string::npos) << text;
    const std::string message = refusal(c.dir, "particleMesh");
    EXPECT_NE(message.find("is in use"), std::string::npos) << message;
    EXPECT_NE(message.find("process " + std::to_string(::getpid())), std::string::npos) << message;
    EXPECT_NE(message.find("isphLandslideFoam -case x"), std::string::npos) << message;
    EXPECT_TRUE(fs::exists(c.lock())) << "the refused one must leave the holder's lock";
  }
  EXPECT_FALSE(fs::exists(c.lock())) << "the holder removes it at its end";
  EXPECT_TRUE(fs::is_empty(c.dir)) << "nothing else left";
}

TEST(CaseLock, TakesOverTheLockOfAnEndedProcessSayingSo) {
  Case c;
  const long pid = endedPid();
  std::ofstream(c.lock()) << "pid          " << pid << "\nhost         " << thisHost()
                          << "\nstarted      2026-12-06 07:00:00 UTC\ncommand      isphLandslideFoam\n";
  std::string taken;
  {
    const CaseLock lock(c.dir, "isphLandslideFoam", taken);
    EXPECT_NE(taken.find("Took over the case lock"), std::string::npos) << taken;
    EXPECT_NE(taken.find("process " + std::to_string(pid)), std::string::npos) << taken;
    EXPECT_NE(readFileBytes(c.lock()).find("pid          " + std::to_string(::getpid())), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(c.lock()));
}

TEST(CaseLock, TakesOverALockWhosePidIsNowAnotherProcess) {
  Case c;  // this process's pid, but another start: a pid reused after a reboot or a long time
  std::ofstream(c.lock()) << "pid          " << ::getpid() << "\nhost         " << thisHost()
                          << "\nprocessStart 1\nstarted      2020-01-01 00:00:00 UTC\ncommand      particleMesh\n";
  std::string taken;
  const CaseLock lock(c.dir, "isphLandslideFoam", taken);
  EXPECT_NE(taken.find("Took over"), std::string::npos) << taken;
}

TEST(CaseLock, RefusesAnotherHostsLockWithTheWayToRemoveIt) {
  Case c;
  std::ofstream(c.lock()) << "pid          " << endedPid() << "\nhost         elsewhere-" << thisHost()
                          << "\nstarted      2026-12-06 07:00:00 UTC\ncommand      isphLandslideFoam -parallel\n";
  const std::string message = refusal(c.dir, "isphLandslideFoam");
  EXPECT_NE(message.find("on host elsewhere-"), std::string::npos) << message;
  EXPECT_NE(message.find("if it has ended, remove " + c.lock().string()), std::string::npos) << message;
  EXPECT_TRUE(fs::exists(c.lock()));
}

}  // namespace
