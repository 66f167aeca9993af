#include "core/app/TimeOptions.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

TimeSelection timeSelection(const ArgList& args) {
  TimeSelection sel;
  sel.ranges = args.option("time");
  sel.latestTime = args.found("latestTime");
  sel.noZero = args.found("noZero");
  return sel;
}

std::vector<Instant> selectedTimes(const ArgList& args, EmptySelection empty) {
  // -parallel: the times of the decomposed case (processor0's; parallel/DecomposedCase.hpp).
  const auto dir = args.found("parallel") ? args.casePath() / "processor0" : args.casePath();
  const auto all = listTimes(dir);
  auto times = selectTimes(all, timeSelection(args));
  if (times.empty()) {
    const std::string message =
        fmt::format("no time directory selected in {} ({} time directories found)", dir.string(), all.size());
    if (empty == EmptySelection::error) fatalError(message + ": nothing to do");
    warning(message);
  }
  return times;
}

}  // namespace isph
