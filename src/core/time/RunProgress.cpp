// Progress of a run: fraction done, recent rate, wall time left, the status line.
#include "core/time/RunProgress.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace isph {

namespace {
constexpr double sampleSpacing = 1;          // wall seconds between kept samples
constexpr double maxDuration = 1000 * 3600;  // formatDuration's "?" from here on
}  // namespace

RunProgress::RunProgress(double wallStart, double startTime, double rateWindow)
    : wallStart_(wallStart),
      startTime_(startTime),
      rateWindow_(rateWindow),
      wall_(wallStart),
      time_(startTime),
      samples_{{wallStart, startTime}} {}

void RunProgress::advance(double wall, double time) {
  wall_ = std::max(wall, wall_);
  time_ = time;
  if (wall_ - samples_.back().wall >= sampleSpacing) samples_.push_back({wall_, time_});
  while (samples_.size() > 1 && samples_[1].wall <= wall_ - rateWindow_) samples_.pop_front();
}

double RunProgress::fraction(double endTime) const {
  const double span = endTime - startTime_;
  if (!(span > 0)) return 1;
  return std::clamp((time_ - startTime_) / span, 0.0, 1.0);
}

std::optional<double> RunProgress::rate() const {
  const Sample& from = samples_.front();
  const double dWall = wall_ - from.wall;
  const double dTime = time_ - from.time;
  if (!(dWall > 0) || !(dTime > 0)) return std::nullopt;
  return dTime / dWall;
}

std::optional<double> RunProgress::secondsLeft(double endTime) const {
  if (finished(endTime)) return 0.0;
  const auto r = rate();
  if (!r) return std::nullopt;
  return (endTime - time_) / *r;
}

bool RunProgress::finished(double endTime) const {
  return time_ >= endTime - 1e-9 * std::max(std::abs(endTime - startTime_), 1e-300);
}

std::string RunProgress::statusLine(const std::string& application, double endTime,
                                    const std::string& tail) const {
  // Whole percent, rounded down: 100% only at the end.
  const int percent = static_cast<int>(std::floor(100 * fraction(endTime) + 1e-9));
  std::string line = fmt::format("{}  t = {:.4g} s / {:.4g} s ({}%)  wall {}", application, time_,
                                 endTime, percent, formatDuration(wallSeconds()));
  if (!tail.empty()) return line + "  " + tail;
  if (const auto left = secondsLeft(endTime)) line += "  left ~" + formatDuration(*left);
  return line;
}

std::string RunProgress::formatDuration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0 || seconds >= maxDuration) return "?";
  const auto total = static_cast<long long>(std::floor(seconds));
  const long long h = total / 3600, m = total / 60 % 60, s = total % 60;
  if (h > 0) return fmt::format("{}:{:02}:{:02}", h, m, s);
  return fmt::format("{}:{:02}", m, s);
}

}  // namespace isph
