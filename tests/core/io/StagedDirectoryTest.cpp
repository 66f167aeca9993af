// StagedDirectory: a directory appears whole on commit() or not at all; recoverStaging
// clears (or restores) what an interrupted run left.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "IoTestHelpers.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/StagingNames.hpp"
#include "core/io/StagingRecovery.hpp"

namespace isph {
namespace {

using iotest::contains;
using iotest::deadPid;
using iotest::expectFatal;
using iotest::readText;
using iotest::TempDir;
using iotest::writeText;

namespace fs = std::filesystem;

// What recoverStaging restored and removed in `dir`.
int recovered(const fs::path& dir) {
  const StagingRecovery r = recoverStaging(dir);
  return r.restored + r.removed;
}

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(StagedDirectory, StagesUnderAHiddenNameAndCommits) {
  TempDir tmp;
  const fs::path target = tmp / "0.1";
  {
    StagedDirectory staged(target);
    EXPECT_EQ(staged.target(), target);
    EXPECT_EQ(staged.path().parent_path(), tmp.path());
    EXPECT_EQ(staged.path().filename().string().rfind(".0.1.tmp.", 0), 0u) << staged.path();
    EXPECT_TRUE(fs::is_directory(staged.path()));
    writeFileAtomic(staged.path() / "time", "value 0.1;\n");
    fs::create_directories(staged.path() / "lagrangian/particles");
    writeFileAtomic(staged.path() / "lagrangian/particles/d", "data");
    EXPECT_FALSE(fs::exists(target));  // not visible before commit
    staged.commit();
    EXPECT_TRUE(staged.committed());
    EXPECT_EQ(staged.path(), target);
  }
  EXPECT_EQ(readText(target / "time"), "value 0.1;\n");
  EXPECT_EQ(readText(target / "lagrangian/particles/d"), "data");
  EXPECT_EQ(entries(tmp.path()), std::vector<std::string>{"0.1"});
}

TEST(StagedDirectory, TrailingSlashNamesTheSameDirectory) {
  TempDir tmp;
  StagedDirectory staged(tmp.path() / "0.2" / "");
  EXPECT_EQ(staged.target(), tmp / "0.2");
  staged.commit();
  EXPECT_TRUE(fs::is_directory(tmp / "0.2"));
}

TEST(StagedDirectory, DestroyedWithoutCommitLeavesThePreviousTarget) {
  TempDir tmp;
  const fs::path target = tmp / "0.1";
  writeText(target / "U", "previous");
  {
    StagedDirectory staged(target);
    writeText(staged.path() / "U", "half");  // the run dies (an exception) before commit()
  }
  EXPECT_EQ(readText(target / "U"), "previous");
  EXPECT_EQ(entries(tmp.path()), std::vector<std::string>{"0.1"});
}

TEST(StagedDirectory, KilledBeforeCommitLeavesOnlyAHiddenDirectory) {
  TempDir tmp;
  const fs::path target = tmp / "0.1";
  writeText(target / "U", "previous");
  // What a killed process leaves: its staging directory (destructor never ran).
  const fs::path leftover = stagingName(target, "tmp");
  writeText(leftover / "U", "half");
  writeText(tmp / fmt::format(".0.2.tmp.{}/U", deadPid()), "half");
  for (const auto& name : entries(tmp.path())) {
    EXPECT_TRUE(name == "0.1" || name[0] == '.') << name;  // a time listing sees only 0.1
  }
  EXPECT_EQ(recovered(tmp.path()), 2);
  EXPECT_EQ(entries(tmp.path()), std::vector<std::string>{"0.1"});
  EXPECT_EQ(readText(target / "U"), "previous");
}

TEST(StagedDirectory, CommitReplacesAnExistingDirectory) {
  TempDir tmp;
  const fs::path target = tmp / "0.1";
  writeText(target / "U", "previous");
  writeText(target / "onlyInOld", "x");
  StagedDirectory staged(target);
  writeText(staged.path() / "U", "new");
  staged.commit();
  EXPECT_EQ(readText(target / "U"), "new");
  EXPECT_FALSE(fs::exists(target / "onlyInOld"));
  EXPECT_EQ(entries(tmp.path()), std::vector<std::string>{"0.1"});  // no .old. left
}

TEST(StagedDirectory, CommitTwiceIsAnError) {
  TempDir tmp;
  StagedDirectory staged(tmp / "0.1");
  staged.commit();
  const auto e = expectFatal([&] { staged.commit(); });
  EXPECT_TRUE(contains(e.what(), "already committed")) << e.what();
}

TEST(StagedDirectory, CannotCreateIsAFatalErrorNamingThePath) {
  TempDir tmp;
  const fs::path target = tmp / "missing/parent/0.1";
  const auto e = expectFatal([&] { StagedDirectory staged(target); });
  EXPECT_TRUE(contains(e.what(), (tmp / "missing/parent").string())) << e.what();
  EXPECT_TRUE(contains(e.what(), "No such file or directory")) << e.what();
}

TEST(StagedDirectory, RestartRestoresADirectoryCaughtBetweenTheTwoRenames) {
  // Killed in commit() after moving the old 0.1 aside and before moving the new one in.
  TempDir tmp;
  const long pid = deadPid();
  writeText(tmp / fmt::format(".0.1.old.{}/U", pid), "committed");
  writeText(tmp / fmt::format(".0.1.tmp.{}/U", pid), "new");
  EXPECT_EQ(recovered(tmp.path()), 2);
  EXPECT_EQ(entries(tmp.path()), std::vector<std::string>{"0.1"});
  EXPECT_EQ(readText(tmp / "0.1/U"), "committed");
}

TEST(StagedDirectory, RestartRemovesAnOldDirectoryWhoseReplacementIsInPlace) {
  // Killed in commit() after the new 0.1 was in place, while the old one was being removed.
  TempDir tmp;
  writeText(tmp / "0.1/U", "new");
  writeText(tmp / fmt::format(".0.1.old.{}/U", deadPid()), "old");
  EXPECT_EQ(recovered(tmp.path()), 1);
  EXPECT_EQ(entries(tmp.path()), std::vector<std::string>{"0.1"});
  EXPECT_EQ(readText(tmp / "0.1/U"), "new");
}

TEST(RecoverStaging, LeavesOtherEntriesAlone) {
  TempDir tmp;
  writeText(tmp / "0.1/U", "x");
  writeText(tmp / ".hidden", "x");          // hidden, but not a staging name
  writeText(tmp / "notes.tmp.txt", "x");    // not hidden
  writeText(tmp / fmt::format(".U.tmp.{}.0", deadPid()), "half");  // a writeFileAtomic temporary
  EXPECT_EQ(recovered(tmp.path()), 1);
  EXPECT_EQ(entries(tmp.path()), (std::vector<std::string>{".hidden", "0.1", "notes.tmp.txt"}));
  EXPECT_EQ(recovered(tmp.path()), 0);
  EXPECT_EQ(recovered(tmp / "doesNotExist"), 0);
}

}  // namespace
}  // namespace isph
