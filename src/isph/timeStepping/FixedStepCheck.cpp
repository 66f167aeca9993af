#include "isph/timeStepping/FixedStepCheck.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Error.hpp"
#include "core/ParallelRun.hpp"
#include "core/time/ProgressReporter.hpp"

namespace isph {

FixedStepCheck::FixedStepCheck(const Time& time)
    : active_(!time.settings().adjustTimeStep), maxCo_(time.settings().maxCo) {}

void FixedStepCheck::check(const Time& time, const StepReport& report, const std::string& lastWritten,
                           ProgressReporter& progress) {
  if (!active_) return;
  ++steps_;
  largest_ = std::max(largest_, report.courant);
  // (parallel: every rank stops alike; the crossings are counted per rank)
  const bool crossed = agreeOverRanks(report.wallCrossings > 0 ? 1 : 0) != 0;
  if (report.courant > courantBound || crossed) {
    const std::string past = report.courant > courantBound
                                 ? fmt::format("Co {:.3g} > {}", report.courant, courantBound)
                                 : std::string("a particle crossed a wall");
    const std::string message = fmt::format(
        "the fixed time step deltaT {:.4g} s (adjustTimeStep no) is past the stability bound at time {}: {} "
        "(the bound: Co <= {} and no wall crossing).\n    The run stops; the last time written, {}, was written "
        "before it and is whole: restart from it with a smaller deltaT, or adjustTimeStep yes (maxCo {}).",
        time.deltaT(), time.timeName(), past, courantBound, lastWritten, maxCo_);
    progress.note("--> FATAL ERROR: " + message);
    fatalError(message);
  }
  if (report.courant <= maxCo_) return;
  if (++above_ == 1) {
    const std::string message =
        fmt::format("the fixed time step deltaT {:.4g} s (adjustTimeStep no) gives Co {:.3g} at time {}, above maxCo "
                    "{}: a smaller deltaT, or adjustTimeStep yes, keeps it (the run stops past Co {})",
                    time.deltaT(), report.courant, time.timeName(), maxCo_, courantBound);
    warning(message);
    progress.note("--> Warning: " + message);
  }
}

std::string FixedStepCheck::summary() const {
  if (above_ == 0) return {};
  return fmt::format("Steps above maxCo {} (adjustTimeStep no): {} of {}, the largest Co {:.3g}", maxCo_, above_,
                     steps_, largest_);
}

}  // namespace isph
