#pragma once
// Selecting times for post-processing as OpenFOAM's timeSelector does:
// `-time '0:0.5,1,2:'`, `-latestTime`, `-noZero`.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/time/TimeName.hpp"

namespace isph {

// The options of a post-processing utility. With neither `ranges` nor `latestTime` every
// time is selected; `ranges` and `latestTime` together select the union; `noZero` then
// drops time 0.
struct TimeSelection {
  std::optional<std::string> ranges;  // the -time argument
  bool latestTime = false;
  bool noZero = false;
};

// One item of a -time argument: a single value, or an inclusive range with optional bounds.
struct TimeRange {
  std::optional<double> lower;
  std::optional<double> upper;
  bool single = false;  // "a": the existing time nearest to `lower`
};

// Parse "0:0.5,1,2:" (items separated by ',' and/or whitespace; forms a, a:b, :b, a:).
// A malformed string is a FatalError naming -time and the forms expected.
std::vector<TimeRange> parseTimeRanges(std::string_view text);

// The times of `all` (sorted, as listTimes gives them) that `sel` selects, in order. A single
// value picks the time nearest to it within a relative tolerance of 1e-6 (a value that matches
// no time selects nothing); range bounds are inclusive. An empty result is not an error here.
std::vector<Instant> selectTimes(const std::vector<Instant>& all, const TimeSelection& sel);

}  // namespace isph
