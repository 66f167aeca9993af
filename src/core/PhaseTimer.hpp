#pragma once
// Wall-clock time spent in each named phase of a run (neighbour search, PPE solve, ...),
// accumulated over all steps and printed as a table at the end of the run.
//
//   PhaseTimer timer;
//   { auto scope = timer.scope("PPE solve"); solve(); }
#include <chrono>
#include <string>
#include <vector>

namespace isph {

class PhaseTimer {
 public:
  class Scope {
   public:
    Scope(PhaseTimer& timer, std::size_t phase);
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;
    ~Scope();

   private:
    PhaseTimer& timer_;
    std::size_t phase_;
    std::chrono::steady_clock::time_point start_;
  };

  // Phases appear in the table in the order they were first used.
  Scope scope(const std::string& phase);
  // Add time measured elsewhere (e.g. a solver's own setup and solve times).
  void add(const std::string& phase, double seconds);
  double seconds(const std::string& phase) const;
  double totalSeconds() const;
  // "phase  seconds  share" lines.
  std::string table() const;

 private:
  std::vector<std::string> names_;
  std::size_t indexOf(const std::string& phase);
  std::vector<double> seconds_;
};

}  // namespace isph
