#pragma once
// Post-processing over the selected times goes on past a time directory it cannot read (one
// half-written by a run that was killed, a field damaged or removed by hand): that time is
// skipped with a warning that gives the reason, and the end of the run says how many were.
// Only when none of the times can be read is it an error (and a non-zero exit).
//
//   SkippedTimes skipped;
//   for (const auto& time : times) {
//     const auto cloud = skipped.read(time, [&] { return readCloud(casePath / time.name, name); });
//     if (!cloud) continue;
//     ...
//   }
//   skipped.finish(times.size());
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>

#include "core/Error.hpp"
#include "core/time/TimeName.hpp"

namespace isph {

class SkippedTimes {
 public:
  // What read() returns, or nullopt after a warning that `time` is skipped and why.
  template <class Read>
  std::optional<std::invoke_result_t<Read>> read(const Instant& time, Read&& read) {
    try {
      return std::forward<Read>(read)();
    } catch (const FatalError& e) {
      skip(time, e);
      return std::nullopt;
    }
  }

  std::size_t count() const { return count_; }
  // A closing warning with the number skipped; FatalError when all `selected` were.
  void finish(std::size_t selected) const;

 private:
  void skip(const Instant& time, const FatalError& e);

  std::size_t count_ = 0;
};

}  // namespace isph
