// A function object's table under faults (issue 54): a write that fails gives the reason and
// leaves whole rows only; the first write leaves the previous file as it was; a half row left by
// a crash is dropped at the next start.
#include "postProcessing/functionObjects/RowFile.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>

#include "core/Error.hpp"
#include "core/io/ReadFile.hpp"

namespace {

using namespace isph;
namespace fs = std::filesystem;

struct Dir {
  fs::path path = fs::temp_directory_path() / ("isphRowFile-" + std::to_string(::getpid()));
  Dir() { fs::remove_all(path), fs::create_directories(path / "0"); }
  ~Dir() { fs::remove_all(path); }
};

// The file size limit (RLIMIT_FSIZE) set to `bytes` for the scope, SIGXFSZ ignored: a write past
// it fails with EFBIG ("File too large"), as one on a full disk fails with ENOSPC.
struct FileSizeLimit {
  rlimit old{};
  explicit FileSizeLimit(rlim_t bytes) {
    std::signal(SIGXFSZ, SIG_IGN);
    ::getrlimit(RLIMIT_FSIZE, &old);
    rlimit limit = old;
    limit.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() { ::setrlimit(RLIMIT_FSIZE, &old); }
};

std::string row(int i) { return std::to_string(i) + "\t1.2345678\t-9.8765432\n"; }

TEST(RowFile, AFailedAppendGivesTheReasonAndLeavesWholeRowsOnly) {
  Dir dir;
  const fs::path file = dir.path / "0" / "force.dat";
  RowFile out(file, "function object 'wallForce'");
  out.write("# Time\tFx\tFy\n" + row(0));
  std::string message;
  int rows = 1;
  {
    const FileSizeLimit limit(200);  // the header and a few rows
    try {
      for (; rows < 100; ++rows) out.write(row(rows) + row(rows));  // (two rows a write: one cut in two)
    } catch (const FatalError& e) {
      message = e.what();
    }
  }
  ASSERT_FALSE(message.empty()) << "no write failed";
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;  // the reason (was none)
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
  EXPECT_NE(message.find("wallForce"), std::string::npos) << message;
  const std::string text = readFileBytes(file);
  EXPECT_LE(text.size(), 200u);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "a half row was left: " << text;
  EXPECT_EQ(text, "# Time\tFx\tFy\n" + [&] {
    std::string whole = row(0);
    for (int i = 1; i < rows; ++i) whole += row(i) + row(i);
    return whole;
  }()) << "the rows before the failed write must stay";
}

TEST(RowFile, AFailedFirstWriteLeavesThePreviousFileAsItWas) {
  Dir dir;
  const fs::path file = dir.path / "0" / "force.dat";
  const std::string previous = "# Time\tFx\n0\t1\n0.1\t2\n";
  std::ofstream(file) << previous;
  RowFile out(file, "function object 'wallForce'");
  std::string message;
  {
    const FileSizeLimit limit(10);  // not even the header
    try {
      out.write("# Time\tFx\n0\t1\n");
    } catch (const FatalError& e) {
      message = e.what();
    }
  }
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  EXPECT_EQ(readFileBytes(file), previous) << "a failed restart emptied the table";
}

TEST(RowFile, AHalfRowLeftByACrashIsDroppedAtTheNextStart) {
  Dir dir;
  fs::create_directories(dir.path / "0.5");
  std::ofstream(dir.path / "0" / "force.dat") << "# Time\tFx\n0\t1\n0.1\t2\n0.2\t3.14";
  std::ofstream(dir.path / "0.5" / "force.dat") << "# Time\tFx\n0.5\t1\n";
  dropHalfRows(dir.path, "force.dat");
  EXPECT_EQ(readFileBytes(dir.path / "0" / "force.dat"), "# Time\tFx\n0\t1\n0.1\t2\n");
  EXPECT_EQ(readFileBytes(dir.path / "0.5" / "force.dat"), "# Time\tFx\n0.5\t1\n") << "a whole table is kept";
}

}  // namespace
