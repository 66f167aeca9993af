// Parsing -time ranges and selecting times.
#include "core/time/TimeSelector.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/Error.hpp"

namespace isph {

namespace {

constexpr double relTol = 1e-6;

[[noreturn]] void badRanges(std::string_view text, const std::string& why) {
  fatalError(fmt::format(
      "option -time '{}': {}\n    expected times and ranges separated by commas, e.g. -time '0.1', "
      "'0:0.5' (inclusive), ':0.2' (up to), '1:' (from), '0.1,0.3,1:'",
      text, why));
}

double parseBound(std::string_view text, std::string_view bound) {
  double v = 0;
  if (!parseTimeName(bound, v)) badRanges(text, fmt::format("'{}' is not a number", bound));
  return v;
}

bool within(double t, double bound, bool below) {
  const double slack = relTol * std::max(std::abs(t), std::abs(bound));
  return below ? t <= bound + slack : t >= bound - slack;
}

}  // namespace

std::vector<TimeRange> parseTimeRanges(std::string_view text) {
  std::vector<TimeRange> ranges;
  std::size_t i = 0;
  auto isSeparator = [](char c) { return c == ',' || c == ' ' || c == '\t' || c == '\n'; };
  while (i < text.size()) {
    if (isSeparator(text[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && !isSeparator(text[j])) ++j;
    const std::string_view item = text.substr(i, j - i);
    i = j;

    TimeRange range;
    const auto colon = item.find(':');
    if (colon == std::string_view::npos) {
      range.lower = range.upper = parseBound(text, item);
      range.single = true;
    } else {
      if (item.find(':', colon + 1) != std::string_view::npos) {
        badRanges(text, fmt::format("'{}' has more than one ':'", item));
      }
      const std::string_view lo = item.substr(0, colon), hi = item.substr(colon + 1);
      if (lo.empty() && hi.empty()) badRanges(text, "':' needs a lower or an upper bound");
      if (!lo.empty()) range.lower = parseBound(text, lo);
      if (!hi.empty()) range.upper = parseBound(text, hi);
      if (range.lower && range.upper && *range.lower > *range.upper) {
        badRanges(text, fmt::format("range '{}' has its lower bound above its upper bound", item));
      }
    }
    ranges.push_back(range);
  }
  if (ranges.empty()) badRanges(text, "no time given");
  return ranges;
}

std::vector<Instant> selectTimes(const std::vector<Instant>& all, const TimeSelection& sel) {
  std::vector<bool> chosen(all.size(), !sel.ranges && !sel.latestTime);
  if (sel.ranges) {
    for (const TimeRange& r : parseTimeRanges(*sel.ranges)) {
      if (r.single) {
        if (const Instant* t = findTime(all, *r.lower, relTol))
          chosen[static_cast<std::size_t>(t - all.data())] = true;
        continue;
      }
      for (std::size_t k = 0; k < all.size(); ++k) {
        if ((!r.lower || within(all[k].value, *r.lower, false)) &&
            (!r.upper || within(all[k].value, *r.upper, true))) {
          chosen[k] = true;
        }
      }
    }
  }
  if (sel.latestTime && !all.empty()) chosen.back() = true;
  std::vector<Instant> out;
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (chosen[k] && !(sel.noZero && all[k].value == 0)) out.push_back(all[k]);
  }
  return out;
}

}  // namespace isph
