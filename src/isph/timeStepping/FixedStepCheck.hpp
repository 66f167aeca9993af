#pragma once
// With adjustTimeStep no the step is the user's, and nothing shortens it when the flow speeds up.
// After every step, before its time can be written:
//  - a step with Co above controlDict's maxCo is a warning, in the log and on the terminal (the
//    first such step; the end of the run counts them);
//  - a step past the stability bound, Co > 1 (a particle travels more than a smoothing length
//    in a step) or a particle crossing a wall, stops the run with a FatalError that says so and
//    names the last time written, which every step before it kept within the bound: that time is
//    whole and a restart from it (with a smaller deltaT, or adjustTimeStep yes) is sound. The
//    step past the bound is not written.
// With adjustTimeStep yes it does nothing: the step follows maxCo (TimeStepControl.hpp).
#include <string>

#include "core/time/Time.hpp"
#include "isph/timeStepping/StepReport.hpp"

namespace isph {

class ProgressReporter;

class FixedStepCheck {
 public:
  static constexpr double courantBound = 1.0;

  explicit FixedStepCheck(const Time& time);

  // The step to time.value() just taken (report); lastWritten: the name of the last time
  // directory written (the start time before any).
  void check(const Time& time, const StepReport& report, const std::string& lastWritten, ProgressReporter& progress);
  // "Steps above maxCo 0.4 (adjustTimeStep no): 12 of 300, the largest Co 0.8"; empty when none.
  std::string summary() const;

 private:
  bool active_;
  double maxCo_;
  long steps_ = 0, above_ = 0;
  double largest_ = 0;
};

}  // namespace isph
