#pragma once
// Post-processing over the selected times stops at a time directory it cannot read (one
// half-written by a run that was killed, a field damaged or removed by hand) with a FatalError
// that names the time, the reason and the option -skipDamaged (a non-zero exit, as OpenFOAM's:
// a script can tell; the times before it are done). With -skipDamaged such a time is skipped with
// a warning that gives the reason, and the end of the run says how many were; when none of the
// times can be read it is still an error.
//
//   const isph::ApplicationSpec spec{..., .options = {..., isph::SkippedTimes::option()}, ...};
//   SkippedTimes skipped(args);
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
#include "core/app/ArgList.hpp"
#include "core/time/TimeName.hpp"

namespace isph {

class SkippedTimes {
 public:
  // -skipDamaged, for the application's options (its -help names it). (A function: the specs
  // are namespace-scope constants of other files, initialised in an order of their own.)
  static OptionSpec option();

  explicit SkippedTimes(const ArgList& args);

  // What read() returns; with -skipDamaged nullopt after a warning that `time` is skipped and
  // why, without it a FatalError saying so.
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

  bool carryOn_ = false;
  std::size_t count_ = 0;
};

}  // namespace isph
