#include "core/app/SkippedTimes.hpp"

#include <fmt/format.h>

namespace isph {

OptionSpec SkippedTimes::option() {
  return {"skipDamaged", "",
          "carry on past a selected time that cannot be read (incomplete or damaged) with a warning, instead of "
          "stopping there with an error"};
}

SkippedTimes::SkippedTimes(const ArgList& args) : carryOn_(args.found(option().name)) {}

void SkippedTimes::skip(const Instant& time, const FatalError& e) {
  if (!carryOn_) {
    throw FatalError(fmt::format("time {} cannot be read (incomplete or damaged), stopped there (the times before it "
                                 "are done; -skipDamaged carries on past such a time):\n{}",
                                 time.name, e.what()),
                     e.where());
  }
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
