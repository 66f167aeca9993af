#pragma once
// Points from a CSV file of the case (a surveyed ground surface, a slip surface): one point
// a line, comma separated; '#' comment lines and blank lines are skipped. An optional header
// line names the columns: x and y are then picked by name (other columns are ignored),
// otherwise the first two columns are x and y. Errors name the CSV file and its line.
#include <filesystem>
#include <vector>

#include "core/Error.hpp"
#include "geometry/Vec2.hpp"

namespace isph {

struct CsvPoints {
  std::vector<Vec2> points;
  std::vector<int> lines;  // the line of each point (1-based)
};

// `namedAt` is where the dictionary names the file (used when the file cannot be opened).
CsvPoints readCsvPoints(const std::filesystem::path& file, const SourceLocation& namedAt);

}  // namespace isph
