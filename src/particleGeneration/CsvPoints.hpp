#pragma once
// Points from a CSV file of the case (a surveyed ground surface, a slip surface): one point
// a line, comma separated; '#' comment lines and blank lines are skipped. An optional header
// line names the columns: x and y are then picked by name (other columns are ignored),
// otherwise the first two columns are x and y. Errors name the CSV file and its line; a value
// that is not a finite number (nan, inf, 1e400) is one. Limits: a regular file of at most
// 256 MiB, lines of at most 1 MiB and 1024 columns.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/Error.hpp"
#include "geometry/Vec2.hpp"

namespace isph {

struct CsvPoints {
  std::vector<Vec2> points;
  std::vector<int> lines;  // the line of each point (1-based)
};

// `namedAt` is where the dictionary names the file (used when the file cannot be read).
CsvPoints readCsvPoints(const std::filesystem::path& file, const SourceLocation& namedAt);

// The same from the text of a CSV file; `fileName` is what errors name.
CsvPoints parseCsvPoints(std::string_view text, const std::string& fileName);

}  // namespace isph
