// Progress of a run on a terminal or a pipe: rate-limited status lines, failure-proof writes.
#include "core/time/ProgressReporter.hpp"

#include "core/ParallelRun.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <string_view>

namespace isph {

namespace {

enum class WriteResult { written, skipped, failed };

// Writes `text` to `fd`. SIGPIPE is blocked around the write and one that it raised is
// taken back, so a reader that went away gives EPIPE (failed) instead of killing the process.
WriteResult writeQuietly(int fd, std::string_view text) {
  const int savedErrno = errno;
  sigset_t pipeSet, oldMask, pending;
  sigemptyset(&pipeSet);
  sigaddset(&pipeSet, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipeSet, &oldMask);
  sigpending(&pending);
  const bool pipeWasPending = sigismember(&pending, SIGPIPE) == 1;

  WriteResult result = WriteResult::written;
  bool brokenPipe = false;
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n > 0) {
      text.remove_prefix(static_cast<std::size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      // A non-blocking descriptor that is full: drop this line, try the next one.
      const bool full = n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK);
      brokenPipe = n < 0 && errno == EPIPE;
      result = full ? WriteResult::skipped : WriteResult::failed;
      break;
    }
  }
  if (brokenPipe && !pipeWasPending) {
    const timespec noWait{};
    while (sigtimedwait(&pipeSet, nullptr, &noWait) < 0 && errno == EINTR) {
    }
  }
  pthread_sigmask(SIG_SETMASK, &oldMask, nullptr);
  errno = savedErrno;
  return result;
}

}  // namespace

ProgressReporter::ProgressReporter(std::string application, double startTime)
    : ProgressReporter(std::move(application), startTime, environmentFd(), Style::lines) {
  if (fd_ >= 0 && ::isatty(fd_)) style_ = Style::terminal;
}

ProgressReporter::ProgressReporter(std::string application, double startTime, int fd, Style style,
                                   Clock clock)
    : application_(std::move(application)),
      fd_(fd),
      style_(style),
      clock_(std::move(clock)),
      progress_(clock_(), startTime) {}

ProgressReporter::~ProgressReporter() {
  if (lineOpen_) write("\n");
}

int ProgressReporter::environmentFd() {
  if (!isMasterRank()) return -1;  // a parallel run's progress is rank 0's
  const char* value = std::getenv("ISPH_PROGRESS_FD");
  if (!value || !*value) return -1;
  const std::string_view text(value);
  int fd = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), fd);
  if (ec != std::errc{} || end != text.data() + text.size() || fd < 0) return -1;
  return ::fcntl(fd, F_GETFD) == -1 ? -1 : fd;
}

double ProgressReporter::steadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void ProgressReporter::update(double time, double endTime) {
  if (!active()) return;
  progress_.advance(clock_(), time);
  if (!due(endTime)) return;
  const std::string line = progress_.statusLine(application_, endTime);
  if (style_ == Style::terminal) {
    write(overwriting(line));
    lineOpen_ = active();
  } else {
    write(line + "\n");
  }
  written_ = true;
  lastWrite_ = progress_.wallSeconds();
  lastStep_ = step(endTime);
}

void ProgressReporter::note(const std::string& line) {
  if (!active()) return;
  write((lineOpen_ ? "\n" : "") + line + "\n");
  lineOpen_ = false;
  written_ = false;  // (a terminal: the status line again at the next update)
}

void ProgressReporter::noteOnTerminal(const std::string& line) {
  ProgressReporter reporter("", 0);
  reporter.note(line);
  reporter.fd_ = -1;  // (no closing line)
}

void ProgressReporter::finish(double time, double endTime) {
  if (!active()) return;
  progress_.advance(clock_(), time);
  const std::string line =
      progress_.statusLine(application_, endTime, progress_.finished(endTime) ? "done" : "stopped");
  if (style_ == Style::terminal) {
    write(overwriting(line) + "\n");
  } else {
    write(line + "\n");
  }
  lineOpen_ = false;
  fd_ = -1;
}

bool ProgressReporter::due(double endTime) const {
  const double since = progress_.wallSeconds() - lastWrite_;
  if (style_ == Style::terminal) return !written_ || since >= terminalInterval;
  return since >= linesMaxInterval || (step(endTime) > lastStep_ && since >= linesMinInterval);
}

int ProgressReporter::step(double endTime) const {
  return static_cast<int>(std::floor(progress_.fraction(endTime) / linesStep + 1e-9));
}

std::string ProgressReporter::overwriting(const std::string& line) {
  const std::size_t blank = lastLength_ > line.size() ? lastLength_ - line.size() : 0;
  lastLength_ = line.size();
  return "\r" + line + std::string(blank, ' ');
}

void ProgressReporter::write(const std::string& text) {
  if (fd_ < 0) return;
  if (writeQuietly(fd_, text) == WriteResult::failed) {
    fd_ = -1;
    lineOpen_ = false;
  }
}

}  // namespace isph
