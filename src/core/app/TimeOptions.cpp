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

std::vector<Instant> selectedTimes(const ArgList& args) {
  const auto all = listTimes(args.casePath());
  auto times = selectTimes(all, timeSelection(args));
  if (times.empty()) {
    warning(fmt::format("no time directory selected in {} ({} time directories found)", args.casePath().string(),
                        all.size()));
  }
  return times;
}

}  // namespace isph
