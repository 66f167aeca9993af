// ProgressReporter: how often it writes on a terminal and elsewhere, what it writes, the
// environment's descriptor, and writes that fail without harming the run. The clock is a
// variable, so nothing sleeps; the descriptor is a pipe.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <optional>
#include <string>

#include "core/time/ProgressReporter.hpp"

namespace isph {
namespace {

using Style = ProgressReporter::Style;

class Pipe {
 public:
  Pipe() {
    EXPECT_EQ(::pipe(fds_), 0);
    ::fcntl(fds_[0], F_SETFL, O_NONBLOCK);
  }
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  ~Pipe() {
    closeRead();
    closeWrite();
  }
  int writeFd() const { return fds_[1]; }
  void closeRead() { closeFd(fds_[0]); }
  void closeWrite() { closeFd(fds_[1]); }
  // What was written since the last call.
  std::string read() {
    std::string out;
    char buffer[4096];
    ssize_t n;
    while ((n = ::read(fds_[0], buffer, sizeof buffer)) > 0) out.append(buffer, std::size_t(n));
    return out;
  }

 private:
  static void closeFd(int& fd) {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
  int fds_[2]{-1, -1};
};

long count(const std::string& text, char c) { return std::count(text.begin(), text.end(), c); }

// A reporter on a pipe, with a wall clock that the test moves (`wall`, in seconds).
class ProgressReporterOnAPipe : public ::testing::Test {
 protected:
  ProgressReporter& start(Style style) {
    return reporter_.emplace("solver", 0, pipe.writeFd(), style, [this] { return wall; });
  }
  void stop() { reporter_.reset(); }

  Pipe pipe;
  double wall = 1000;

 private:
  std::optional<ProgressReporter> reporter_;
};

TEST_F(ProgressReporterOnAPipe, TerminalRewritesOneLineAtMostFourTimesASecond) {
  ProgressReporter& reporter = start(Style::terminal);
  // 128 steps of 1/64 s: 2 s of wall time, the run from 0 to 1 s
  for (int k = 1; k <= 128; ++k) {
    wall += 1.0 / 64;
    reporter.update(k / 128.0, 1.0);
  }
  const std::string during = pipe.read();
  EXPECT_EQ(count(during, '\r'), 8) << during;  // the first step, then every 0.25 s
  EXPECT_EQ(count(during, '\n'), 0) << during;
  EXPECT_EQ(during.substr(0, 40), "\rsolver  t = 0.007812 s / 1 s (0%)  wall");
  reporter.finish(1.0, 1.0);
  const std::string end = pipe.read();
  // The last line, blanking what is left of the longer one before it.
  std::string last = "\rsolver  t = 1 s / 1 s (100%)  wall 0:02  done";
  last.resize(during.size() - during.rfind('\r'), ' ');
  EXPECT_EQ(end, last + "\n");
}

TEST_F(ProgressReporterOnAPipe, TerminalBlanksTheRestOfALongerLine) {
  ProgressReporter& reporter = start(Style::terminal);
  wall += 1;
  reporter.update(0.01, 100);  // left ~2:46:39
  wall += 1;
  reporter.update(50, 100);  // left ~0:02
  const std::string out = pipe.read();
  EXPECT_EQ(out,
            "\rsolver  t = 0.01 s / 100 s (0%)  wall 0:01  left ~2:46:39"
            "\rsolver  t = 50 s / 100 s (50%)  wall 0:02  left ~0:02    ");
}

TEST_F(ProgressReporterOnAPipe, LinesAtEveryTenthOfTheRun) {
  ProgressReporter& reporter = start(Style::lines);
  // 300 s of wall time at 8 steps a second, the run from 0 to 3 s
  for (int k = 1; k <= 2400; ++k) {
    wall += 0.125;
    reporter.update(3.0 * k / 2400, 3.0);
  }
  const std::string out = pipe.read();
  EXPECT_EQ(count(out, '\r'), 0) << out;
  EXPECT_EQ(count(out, '\n'), 10) << out;  // at 10 %, 20 %, ..., 100 %
  EXPECT_EQ(out.substr(0, out.find('\n')), "solver  t = 0.3 s / 3 s (10%)  wall 0:30  left ~4:30");
  reporter.finish(3.0, 3.0);
  EXPECT_EQ(pipe.read(), "solver  t = 3 s / 3 s (100%)  wall 5:00  done\n");
}

TEST_F(ProgressReporterOnAPipe, LinesAtLeastEveryMinuteOfASlowRun) {
  ProgressReporter& reporter = start(Style::lines);
  for (int k = 1; k <= 200; ++k) {  // 200 s for the first 5 % of the run
    wall += 1;
    reporter.update(0.05 * k / 200, 1.0);
  }
  const std::string out = pipe.read();
  EXPECT_EQ(count(out, '\n'), 3) << out;  // after 60, 120 and 180 s
  EXPECT_NE(out.find("wall 1:00"), std::string::npos) << out;
  EXPECT_NE(out.find("wall 3:00"), std::string::npos) << out;
}

TEST_F(ProgressReporterOnAPipe, LinesNotMoreOftenThanEveryTwoSeconds) {
  ProgressReporter& reporter = start(Style::lines);
  for (int k = 1; k <= 100; ++k) {  // the whole run in 1 s
    wall += 0.01;
    reporter.update(k / 100.0, 1.0);
  }
  EXPECT_EQ(pipe.read(), "");
  reporter.finish(1.0, 1.0);
  EXPECT_EQ(count(pipe.read(), '\n'), 1);
}

TEST_F(ProgressReporterOnAPipe, FinishBeforeEndTimeSaysStopped) {
  ProgressReporter& reporter = start(Style::lines);
  wall += 3;
  reporter.finish(0.25, 1.0);
  EXPECT_EQ(pipe.read(), "solver  t = 0.25 s / 1 s (25%)  wall 0:03  stopped\n");
  EXPECT_FALSE(reporter.active());
  reporter.update(0.5, 1.0);  // reporting has ended
  EXPECT_EQ(pipe.read(), "");
}

TEST_F(ProgressReporterOnAPipe, DestructorEndsAnOpenTerminalLine) {
  ProgressReporter& reporter = start(Style::terminal);
  wall += 1;
  reporter.update(0.5, 1.0);
  stop();  // as a FatalError unwinding the time loop does
  const std::string out = pipe.read();
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back(), '\n');
  EXPECT_EQ(count(out, '\n'), 1);
}

TEST(ProgressReporter, NothingWithoutADescriptor) {
  ::unsetenv("ISPH_PROGRESS_FD");
  EXPECT_EQ(ProgressReporter::environmentFd(), -1);
  ProgressReporter fromEnvironment("solver", 0);
  EXPECT_FALSE(fromEnvironment.active());
  ProgressReporter none("solver", 0, -1, Style::lines);
  EXPECT_FALSE(none.active());
  none.update(1, 1);
  none.finish(1, 1);
  EXPECT_FALSE(none.active());
}

TEST(ProgressReporter, DescriptorFromTheEnvironment) {
  Pipe pipe;
  const std::string fd = std::to_string(pipe.writeFd());
  ::setenv("ISPH_PROGRESS_FD", fd.c_str(), 1);
  EXPECT_EQ(ProgressReporter::environmentFd(), pipe.writeFd());
  {
    ProgressReporter reporter("solver", 0);
    EXPECT_TRUE(reporter.active());
    reporter.finish(1, 1);
  }
  // A pipe is not a terminal: a plain line.
  const std::string out = pipe.read();
  EXPECT_EQ(out.rfind("solver  t = 1 s / 1 s (100%)  wall ", 0), 0u) << out;
  EXPECT_EQ(out.substr(out.size() - 7), "  done\n") << out;

  for (const char* bad : {"", "x", "3x", "-1", " 3", "99999999999"}) {
    ::setenv("ISPH_PROGRESS_FD", bad, 1);
    EXPECT_EQ(ProgressReporter::environmentFd(), -1) << "'" << bad << "'";
  }
  pipe.closeWrite();  // a number, but not an open descriptor
  ::setenv("ISPH_PROGRESS_FD", fd.c_str(), 1);
  EXPECT_EQ(ProgressReporter::environmentFd(), -1);
  ::unsetenv("ISPH_PROGRESS_FD");
}

TEST_F(ProgressReporterOnAPipe, AReaderThatWentAwayDoesNotStopTheRun) {
  const auto previous = std::signal(SIGPIPE, SIG_DFL);  // the action that would end the process
  pipe.closeRead();
  ProgressReporter& reporter = start(Style::terminal);
  wall += 1;
  reporter.update(0.5, 1.0);  // EPIPE; a SIGPIPE delivered would end the test binary here
  EXPECT_FALSE(reporter.active());
  sigset_t pending;
  sigpending(&pending);
  EXPECT_EQ(sigismember(&pending, SIGPIPE), 0) << "no SIGPIPE left pending";
  reporter.finish(1.0, 1.0);
  std::signal(SIGPIPE, previous);
}

TEST_F(ProgressReporterOnAPipe, AClosedDescriptorSwitchesItOff) {
  ProgressReporter& reporter = start(Style::lines);
  pipe.closeWrite();
  wall += 1;
  reporter.finish(1.0, 1.0);  // EBADF
  EXPECT_FALSE(reporter.active());
}

}  // namespace
}  // namespace isph
