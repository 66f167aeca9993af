#pragma once
// Time directory names as OpenFOAM makes them (general format, `timePrecision` significant
// digits: 0.1 -> "0.1", 1e-05 -> "1e-05", 100 -> "100") and the times a case holds.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace isph {

// The name of time `t`: printf "%.<precision>g", so round-off such as 0.30000000000000004
// gives "0.3"; -0 gives "0".
std::string timeName(double t, int precision = 6);

// `text` as a time value when the whole of it is a finite number ("0.1", "1e-05").
bool parseTimeName(std::string_view text, double& value);

// One time directory: its value (parsed from the name) and its name.
struct Instant {
  double value = 0;
  std::string name;
};

// The sub-directories of `caseDir` whose whole name is a number, sorted by value.
// constant/, system/, hidden entries (staging directories ".0.1.tmp.123") and names such
// as "0.orig" are not times. A missing `caseDir` gives an empty list.
std::vector<Instant> listTimes(const std::filesystem::path& caseDir);

// The time in `times` nearest to `value` if it lies within `tolerance` relative to the larger
// magnitude of the two (0 matches only 0), else nullptr.
const Instant* findTime(const std::vector<Instant>& times, double value, double tolerance = 1e-6);

}  // namespace isph
