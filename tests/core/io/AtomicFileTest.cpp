// writeFileAtomic: content arrives whole, and an interrupted write leaves the old file.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>

#include "IoTestHelpers.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/StagingRecovery.hpp"

namespace isph {
namespace {

using iotest::contains;
using iotest::expectFatal;
using iotest::readText;
using iotest::TempDir;

namespace fs = std::filesystem;

// Entries of `dir` whose names start with '.'.
int hiddenEntries(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string()[0] == '.';
  return n;
}

TEST(AtomicFile, WritesAndReadsBack) {
  TempDir tmp;
  const fs::path file = tmp / "U";
  writeFileAtomic(file, "hello\nworld\n");
  EXPECT_EQ(readText(file), "hello\nworld\n");
  EXPECT_EQ(hiddenEntries(tmp.path()), 0);
}

TEST(AtomicFile, ReplacesAnExistingFile) {
  TempDir tmp;
  const fs::path file = tmp / "U";
  writeFileAtomic(file, "old");
  writeFileAtomic(file, std::string(100000, 'x'));
  EXPECT_EQ(readText(file), std::string(100000, 'x'));
  EXPECT_EQ(hiddenEntries(tmp.path()), 0);
}

TEST(AtomicFile, EmptyAndBinaryContent) {
  TempDir tmp;
  writeFileAtomic(tmp / "empty", "");
  EXPECT_EQ(readText(tmp / "empty"), "");
  const std::string bytes("a\0b\xff\n", 5);
  writeFileAtomic(tmp / "bytes", bytes);
  EXPECT_EQ(readText(tmp / "bytes"), bytes);
}

TEST(AtomicFile, InterruptedBeforeRenameLeavesTheOldFile) {
  TempDir tmp;
  const fs::path file = tmp / "p";
  writeFileAtomic(file, "old content");
  // The first half of writeFileAtomic: the new content is on disk, but under a hidden name.
  const fs::path staged = detail::writeStagingFile(file, "new content");
  EXPECT_EQ(staged.parent_path(), file.parent_path());
  EXPECT_EQ(staged.filename().string().rfind(".p.tmp.", 0), 0u) << staged;
  EXPECT_EQ(readText(staged), "new content");
  EXPECT_EQ(readText(file), "old content");  // what a restart would see if the run died now
  // A restart clears the leftover and keeps the old file.
  EXPECT_EQ(recoverStaging(tmp.path()).removed, 1);
  EXPECT_FALSE(fs::exists(staged));
  EXPECT_EQ(readText(file), "old content");
}

TEST(AtomicFile, SecondHalfPublishes) {
  TempDir tmp;
  const fs::path file = tmp / "p";
  writeFileAtomic(file, "old");
  detail::publishStagingFile(detail::writeStagingFile(file, "new"), file);
  EXPECT_EQ(readText(file), "new");
  EXPECT_EQ(hiddenEntries(tmp.path()), 0);
}

TEST(AtomicFile, MissingFolderIsAFatalErrorNamingThePath) {
  TempDir tmp;
  const fs::path file = tmp / "no/such/folder/U";
  const auto e = expectFatal([&] { writeFileAtomic(file, "x"); });
  EXPECT_TRUE(contains(e.what(), file.string())) << e.what();
  EXPECT_TRUE(contains(e.what(), "No such file or directory")) << e.what();
}

TEST(AtomicFile, RenameOverADirectoryFailsAndLeavesNoTemporary) {
  TempDir tmp;
  fs::create_directories(tmp / "d/inside");
  const auto e = expectFatal([&] { writeFileAtomic(tmp / "d", "x"); });
  EXPECT_TRUE(contains(e.what(), "cannot rename")) << e.what();
  EXPECT_TRUE(fs::is_directory(tmp / "d/inside"));
  EXPECT_EQ(hiddenEntries(tmp.path()), 0);
}

TEST(AtomicFile, FailedWriteKeepsTheOldFileAndRemovesTheTemporary) {
  // A file-size limit makes write() fail part-way, as a full disk does.
  TempDir tmp;
  const fs::path file = tmp / "U";
  writeFileAtomic(file, "old");
  struct rlimit saved {};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  struct rlimit small = saved;
  small.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  const auto e = expectFatal([&] { writeFileAtomic(file, std::string(100000, 'x')); });
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, oldHandler);
  EXPECT_TRUE(contains(e.what(), file.string())) << e.what();
  EXPECT_TRUE(contains(e.what(), "File too large")) << e.what();
  EXPECT_EQ(readText(file), "old");
  EXPECT_EQ(hiddenEntries(tmp.path()), 0);
}

TEST(AtomicFile, UnwritableFolderIsAFatalErrorWithTheReason) {
  TempDir tmp;
  fs::create_directories(tmp / "ro");
  fs::permissions(tmp / "ro", fs::perms::owner_read | fs::perms::owner_exec);
  if (::access((tmp / "ro").c_str(), W_OK) == 0)
    GTEST_SKIP() << "running as root: permissions not enforced";
  const auto e = expectFatal([&] { writeFileAtomic(tmp / "ro/U", "x"); });
  fs::permissions(tmp / "ro", fs::perms::owner_all);
  EXPECT_TRUE(contains(e.what(), (tmp / "ro/U").string())) << e.what();
  EXPECT_TRUE(contains(e.what(), "Permission denied")) << e.what();
}

}  // namespace
}  // namespace isph
