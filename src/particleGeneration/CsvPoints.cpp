#include "particleGeneration/CsvPoints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

#include "core/Strings.hpp"

namespace isph {

namespace {

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.emplace_back(trim(std::string_view(line).substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return fields;
}

std::optional<double> parseNumber(const std::string& field) {
  double v = 0;
  const char* begin = field.data();
  const char* end = begin + field.size();
  if (begin != end && *begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, v);
  if (ec != std::errc() || ptr != end || begin == end) return std::nullopt;
  return v;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

CsvPoints readCsvPoints(const std::filesystem::path& file, const SourceLocation& namedAt) {
  std::ifstream in(file);
  if (!in) {
    fatalIOError(namedAt, fmt::format("cannot read the CSV file {} ({})", file.string(),
                                      std::filesystem::exists(file) ? "it exists but cannot be read"
                                                                    : "no such file"));
  }
  const auto name = std::make_shared<const std::string>(file.string());
  auto at = [&](int line) { return SourceLocation{name, line, 0}; };

  CsvPoints out;
  std::size_t xColumn = 0, yColumn = 1;
  bool first = true;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string_view content = trim(line);
    if (content.empty() || content.front() == '#') continue;
    const std::vector<std::string> fields = splitFields(line);
    if (first) {
      first = false;
      const bool header =
          std::any_of(fields.begin(), fields.end(), [](const auto& f) { return !parseNumber(f); });
      if (header) {
        std::vector<std::string> names;
        for (const auto& f : fields) names.push_back(lower(f));
        const auto xi = std::find(names.begin(), names.end(), "x");
        const auto yi = std::find(names.begin(), names.end(), "y");
        if (xi == names.end() || yi == names.end()) {
          fatalIOError(
              at(number),
              fmt::format("the header line of a point file must name columns x and y; found: {}",
                          std::string(content)));
        }
        xColumn = static_cast<std::size_t>(xi - names.begin());
        yColumn = static_cast<std::size_t>(yi - names.begin());
        continue;
      }
    }
    const std::size_t needed = std::max(xColumn, yColumn) + 1;
    if (fields.size() < needed) {
      fatalIOError(
          at(number),
          fmt::format("expected x,y values (at least {} comma-separated fields), found \"{}\"",
                      needed, std::string(content)));
    }
    const auto x = parseNumber(fields[xColumn]);
    const auto y = parseNumber(fields[yColumn]);
    if (!x || !y) {
      fatalIOError(at(number), fmt::format("expected numbers for x and y, found \"{}\" and \"{}\"",
                                           fields[xColumn], fields[yColumn]));
    }
    out.points.emplace_back(*x, *y);
    out.lines.push_back(number);
  }
  if (out.points.empty()) fatalIOError(at(0), "the CSV file holds no points");
  return out;
}

}  // namespace isph
