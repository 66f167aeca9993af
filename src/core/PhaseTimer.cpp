#include "core/PhaseTimer.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace isph {

PhaseTimer::Scope::Scope(PhaseTimer& timer, std::size_t phase)
    : timer_(timer), phase_(phase), start_(std::chrono::steady_clock::now()) {}

PhaseTimer::Scope::~Scope() {
  timer_.seconds_[phase_] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::size_t PhaseTimer::indexOf(const std::string& phase) {
  const auto it = std::find(names_.begin(), names_.end(), phase);
  if (it != names_.end()) return static_cast<std::size_t>(it - names_.begin());
  names_.push_back(phase);
  seconds_.push_back(0.0);
  return names_.size() - 1;
}

PhaseTimer::Scope PhaseTimer::scope(const std::string& phase) { return Scope(*this, indexOf(phase)); }

void PhaseTimer::add(const std::string& phase, double seconds) { seconds_[indexOf(phase)] += seconds; }

double PhaseTimer::seconds(const std::string& phase) const {
  const auto it = std::find(names_.begin(), names_.end(), phase);
  return it == names_.end() ? 0.0 : seconds_[static_cast<std::size_t>(it - names_.begin())];
}

double PhaseTimer::totalSeconds() const {
  double total = 0;
  for (double s : seconds_) total += s;
  return total;
}

namespace {

std::string row(const std::string& name, double seconds, double total) {
  return fmt::format("    {:<34} {:>10.3f} {:>6.1f}%\n", name, seconds, total > 0 ? 100.0 * seconds / total : 0.0);
}

}  // namespace

std::string PhaseTimer::table() const {
  const double total = totalSeconds();
  std::string out = fmt::format("    {:<34} {:>10} {:>7}\n", "phase", "time [s]", "share");
  for (std::size_t i = 0; i < names_.size(); ++i) out += row(names_[i], seconds_[i], total);
  out += fmt::format("    {:<34} {:>10.3f}\n", "total", total);
  return out;
}

std::string PhaseTimer::table(double loopSeconds) const {
  std::string out = fmt::format("    {:<34} {:>10} {:>7}\n", "phase", "time [s]", "share");
  for (std::size_t i = 0; i < names_.size(); ++i) out += row(names_[i], seconds_[i], loopSeconds);
  out += row("other (in no phase)", loopSeconds - totalSeconds(), loopSeconds);
  out += fmt::format("    {:<34} {:>10.3f}\n", "total", loopSeconds);
  return out;
}

}  // namespace isph
