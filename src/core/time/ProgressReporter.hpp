#pragma once
// Shows how far a run is (RunProgress::statusLine) on a file descriptor other than the log:
// etc/RunFunctions' runApplication sends the application's output to log.<app>, hands it the
// caller's stderr as fd 3 and names that fd in ISPH_PROGRESS_FD. Nothing goes to the log.
//
//  - On a terminal (isatty) one line, rewritten after '\r' at most 4 times a second, ended
//    with a newline by finish() (or by the destructor when the run stops with an error).
//  - Elsewhere (a pipe, ctest, a file) few plain lines: one when the run passes another 10 %
//    of its simulated time (at least 2 s of wall time after the previous line), one after
//    60 s without a line, and the last one from finish().
//  - Without a usable fd nothing is written. A write that fails (the reader went away, the
//    fd was closed) switches the reporter off: never an error, never a SIGPIPE.
//
//   ProgressReporter progress("isphLandslideFoam", time.value());  // fd from ISPH_PROGRESS_FD
//   while (time.run()) { ...step...; progress.update(time.value(), time.settings().endTime); }
//   progress.finish(time.value(), time.settings().endTime);
#include <functional>
#include <string>

#include "core/time/RunProgress.hpp"

namespace isph {

class ProgressReporter {
 public:
  enum class Style { terminal, lines };
  using Clock = std::function<double()>;  // wall seconds, monotonic

  static constexpr double terminalInterval = 0.25;  // wall seconds between terminal updates
  static constexpr double linesStep = 0.1;          // a line per this fraction of the run ...
  static constexpr double linesMinInterval = 2;     // ... but not sooner than this after the last
  static constexpr double linesMaxInterval = 60;    // and a line at least this often

  // Reports on environmentFd(), as a terminal when isatty says so.
  ProgressReporter(std::string application, double startTime);
  ProgressReporter(std::string application, double startTime, int fd, Style style,
                   Clock clock = steadySeconds);
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;
  ~ProgressReporter();

  // Whether anything will be written.
  bool active() const { return fd_ >= 0; }
  const RunProgress& progress() const { return progress_; }

  // Once per time step: the run is at `time`; writes a status line when one is due.
  void update(double time, double endTime);
  // A line for the user between the status lines (a warning that the log has too), e.g.
  // "--> Warning: ...": on a terminal the open status line is ended first.
  void note(const std::string& line);
  // The same before a reporter exists (a warning at start): to environmentFd(), if any.
  static void noteOnTerminal(const std::string& line);

  // The last line ("done", or "stopped" before endTime) and, on a terminal, the newline.
  // Reporting ends here.
  void finish(double time, double endTime);

  // The descriptor named by ISPH_PROGRESS_FD when that is a number and an open descriptor;
  // -1 otherwise (unset, empty, not a number, closed).
  static int environmentFd();
  static double steadySeconds();

 private:
  bool due(double endTime) const;
  int step(double endTime) const;
  // "\r" + line, blanking the rest of the previous terminal line.
  std::string overwriting(const std::string& line);
  void write(const std::string& text);

  std::string application_;
  int fd_;
  Style style_;
  Clock clock_;
  RunProgress progress_;
  bool written_ = false;        // a status line was written
  bool lineOpen_ = false;       // a terminal line without its newline yet
  double lastWrite_ = 0;        // wall seconds into the run of the last status line
  int lastStep_ = 0;            // linesStep steps done at the last status line
  std::size_t lastLength_ = 0;  // of the last terminal line, to blank what is left of it
};

}  // namespace isph
