#pragma once
// Wall-clock time spent in each named phase of a run (neighbour search, PPE solve, ...),
// accumulated over all steps and printed as a table at the end of the run (against the time
// loop's wall time: what no phase holds is a row of its own).
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
  // "phase  seconds  share" lines, shares of the phases' total.
  std::string table() const;
  // The same against a loop that took `loopSeconds` on the wall: the time in no phase as the
  // row "other (in no phase)", shares of the loop, and the loop as the total, so that the table
  // adds up to the time the user waited.
  std::string table(double loopSeconds) const;

 private:
  std::vector<std::string> names_;
  std::size_t indexOf(const std::string& phase);
  std::vector<double> seconds_;
};

}  // namespace isph
