// What an interrupted write, replace or purge leaves, and how an application's start restores
// or clears it (issue 34: a kill between the two renames of a replace hid the time; every
// SIGKILL left a .T.tmp behind for good; a purge killed half-way left a half time in view).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include "IoTestHelpers.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/StagingNames.hpp"
#include "core/io/StagingRecovery.hpp"
#include "core/time/TimeName.hpp"

namespace isph {
namespace {

using iotest::deadPid;
using iotest::readText;
using iotest::TempDir;
using iotest::writeText;

namespace fs = std::filesystem;

bool logHas(const StagingRecovery& r, const std::string& text) {
  for (const auto& line : r.log) {
    if (line.find(text) != std::string::npos) return true;
  }
  return false;
}

std::string joined(const StagingRecovery& r) { return fmt::format("{}", fmt::join(r.log, "\n")); }

TEST(StagingNames, RoundTrip) {
  const fs::path dir = stagingName("/case/0.25/", "tmp");
  EXPECT_EQ(dir.parent_path(), fs::path("/case"));
  const auto e = parseStagingName(dir.filename().string());
  ASSERT_TRUE(e);
  EXPECT_EQ(e->target, "0.25");
  EXPECT_EQ(e->kind, "tmp");
  EXPECT_EQ(e->pid, static_cast<long>(::getpid()));
  EXPECT_EQ(e->host, "");  // this host
  const auto file = parseStagingName(stagingName("/case/p", "tmp", 7u).filename().string());
  ASSERT_TRUE(file);
  EXPECT_EQ(file->target, "p");
  const auto trash = parseStagingName(".1e-05.trash.42@node07.cluster");
  ASSERT_TRUE(trash);
  EXPECT_EQ(trash->target, "1e-05");
  EXPECT_EQ(trash->kind, "trash");
  EXPECT_EQ(trash->pid, 42);
  EXPECT_EQ(trash->host, "node07.cluster");
  const auto old = parseStagingName(".U.tmp.123.0");  // written before hosts were recorded
  ASSERT_TRUE(old);
  EXPECT_EQ(old->pid, 123);
  for (const char* notStaging :
       {".hidden", "0.1", ".x.tmp.", ".x.tmp.abc", ".x.old.12.", "..tmp.1"}) {
    EXPECT_FALSE(parseStagingName(notStaging)) << notStaging;
  }
}

TEST(StagingRecovery, ReplaceKilledBetweenItsRenamesRestoresTheTime) {
  TempDir tmp;
  const long pid = deadPid();
  writeText(tmp / fmt::format(".0.5.old.{}/lagrangian/particles/U", pid), "complete");
  writeText(tmp / fmt::format(".0.5.tmp.{}/lagrangian/particles/U", pid), "new");
  EXPECT_TRUE(listTimes(tmp.path()).empty());  // the time is out of view
  const StagingRecovery r = recoverStaging(tmp.path());
  EXPECT_EQ(r.restored, 1);
  EXPECT_EQ(r.removed, 1);
  EXPECT_EQ(readText(tmp / "0.5/lagrangian/particles/U"), "complete");
  ASSERT_EQ(listTimes(tmp.path()).size(), 1u);
  EXPECT_TRUE(logHas(r, "restored " + (tmp / "0.5").string())) << joined(r);
  EXPECT_TRUE(logHas(r, "interrupted between its two renames")) << joined(r);
  EXPECT_TRUE(logHas(r, "an unfinished write")) << joined(r);
}

TEST(StagingRecovery, PurgeKilledHalfWayLeavesNoTimeAndIsCleared) {
  TempDir tmp;
  writeText(tmp / "0.1/lagrangian/particles/U", "x");
  writeText(tmp / "0.2/lagrangian/particles/U", "x");
  removeDirectoryAtomically(tmp / "0.1");
  EXPECT_EQ(listTimes(tmp.path()).size(), 1u);
  // A purge killed after its rename, while deleting: a hidden, half-deleted directory.
  writeText(tmp / fmt::format(".0.2.trash.{}/lagrangian/particles/p", deadPid()), "half");
  fs::remove_all(tmp / "0.2");
  EXPECT_TRUE(listTimes(tmp.path()).empty());
  const StagingRecovery r = recoverStaging(tmp.path());
  EXPECT_EQ(r.removed, 1);
  EXPECT_TRUE(logHas(r, "interrupted removal")) << joined(r);
  EXPECT_TRUE(fs::is_empty(tmp.path()));
}

TEST(StagingRecovery, LeftoversInSubFoldersAreCleared) {
  TempDir tmp;
  const long pid = deadPid();
  writeText(tmp / fmt::format("postProcessing/sampleForces/0/.barrier.dat.tmp.{}.3", pid), "half");
  writeText(tmp / fmt::format("VTK/.case.pvd.tmp.{}.0@{}", pid, thisHost()), "half");
  writeText(tmp / "postProcessing/sampleForces/0/barrier.dat", "whole");
  const StagingRecovery r = recoverStaging(tmp.path());
  EXPECT_EQ(r.removed, 2) << joined(r);
  EXPECT_EQ(readText(tmp / "postProcessing/sampleForces/0/barrier.dat"), "whole");
  EXPECT_EQ(recoverStaging(tmp.path(), {.recursive = false}).removed, 0);
}

// toVTK started while the solver writes: the solver's staging is not touched.
TEST(StagingRecovery, LeftoversOfARunningProcessAreLeftAlone) {
  TempDir tmp;
  const long running = static_cast<long>(::getppid());  // the shell or ctest that started us
  writeText(tmp / fmt::format(".0.7.tmp.{}/U", running), "being written");
  writeText(tmp / fmt::format(".0.6.old.{}/U", running), "being replaced");
  StagingRecovery r = recoverStaging(tmp.path());
  EXPECT_EQ(r.leftAlone, 2);
  EXPECT_EQ(r.restored + r.removed, 0);
  EXPECT_TRUE(logHas(r, fmt::format("process {} may still be writing it", running))) << joined(r);
  EXPECT_FALSE(fs::exists(tmp / "0.6"));
  // A process of another host cannot be asked: left alone, unless the caller writes times.
  writeText(tmp / ".0.8.old.12@elsewhere/U", "previous");
  r = recoverStaging(tmp.path());
  EXPECT_EQ(r.leftAlone, 3);
  EXPECT_TRUE(logHas(r, "process 12 on host elsewhere may still be writing it")) << joined(r);
  r = recoverStaging(tmp.path(), {.ownsForeignHosts = true});
  EXPECT_EQ(r.restored, 1);
  EXPECT_EQ(readText(tmp / "0.8/U"), "previous");
}

}  // namespace
}  // namespace isph
