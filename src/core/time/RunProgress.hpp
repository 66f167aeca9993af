#pragma once
// How far a run is and how long it has left, from (wall-clock, simulated time) samples:
// the fraction of [startTime, endTime] done, the wall time so far and an estimate of the
// wall time left, and the one-line status that ProgressReporter shows.
//
// The estimate divides the simulated time still to go by the recent rate of simulated time
// per wall second: the rate over the last `rateWindow` seconds of wall time (over the whole
// run while it is shorter), so that it follows a run that slows down or speeds up (e.g. the
// time step shrinking as a slide accelerates) without jumping with every step.
//
//   RunProgress p(0.0, 0.0);        // start time 0 at wall second 0
//   p.advance(12.0, 0.3);           // at wall second 12 the run is at t = 0.3
//   p.fraction(1.0);                // 0.3
//   p.secondsLeft(1.0);             // 28 (0.7 s to go at 0.025 s per wall second)
#include <deque>
#include <optional>
#include <string>

namespace isph {

class RunProgress {
 public:
  static constexpr double defaultRateWindow = 30;  // wall seconds

  RunProgress(double wallStart, double startTime, double rateWindow = defaultRateWindow);

  // The run is at simulated time `time` at wall second `wall` (non-decreasing).
  void advance(double wall, double time);

  double time() const { return time_; }
  double startTime() const { return startTime_; }
  double wallSeconds() const { return wall_ - wallStart_; }
  // The fraction of [startTime, endTime] done, in [0, 1] (1 when endTime <= startTime).
  double fraction(double endTime) const;
  // Simulated seconds per wall second over the rate window; nullopt before any progress.
  std::optional<double> rate() const;
  // Wall seconds to endTime at rate(); nullopt when the rate is not known.
  std::optional<double> secondsLeft(double endTime) const;
  // Whether `time` has reached endTime (up to round-off).
  bool finished(double endTime) const;

  // "isphLandslideFoam  t = 0.452 s / 2.5 s (18%)  wall 0:41  left ~3:05"; `tail` replaces
  // the "left ~..." part when given (e.g. "done").
  std::string statusLine(const std::string& application, double endTime,
                         const std::string& tail = "") const;

  // Wall-clock durations as "m:ss" below an hour, "h:mm:ss" above (rounded down to the
  // second); "?" for a negative, non-finite or absurd (1000 h or more) value.
  static std::string formatDuration(double seconds);

 private:
  struct Sample {
    double wall, time;
  };
  double wallStart_, startTime_, rateWindow_;
  double wall_, time_;
  // Samples at least a second apart, the oldest the newest one that is at least rateWindow_
  // old (or the start), so the rate spans a little more than the window.
  std::deque<Sample> samples_;
};

}  // namespace isph
