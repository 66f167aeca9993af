#include "core/app/SkippedTimes.hpp"

#include <fmt/format.h>

namespace isph {

void SkippedTimes::skip(const Instant& time, const FatalError& e) {
  ++count_;
  warning(fmt::format("time {} is skipped: it cannot be read (incomplete or damaged):{}", time.name,
                      e.report()));
}

void SkippedTimes::finish(std::size_t selected) const {
  if (count_ == 0) return;
  if (count_ >= selected) {
    fatalError(fmt::format(
        "none of the {} selected times could be read (the warnings above say why)", selected));
  }
  warning(fmt::format("{} of {} selected times were skipped (the warnings above say why)", count_,
                      selected));
}

}  // namespace isph
