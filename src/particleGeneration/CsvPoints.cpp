#include "particleGeneration/CsvPoints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "core/Strings.hpp"
#include "core/dictionary/Lexer.hpp"
#include "core/io/ReadFile.hpp"

namespace isph {

namespace {

constexpr std::size_t maxFileBytes = std::size_t{256} << 20;
constexpr std::size_t maxLineBytes = std::size_t{1} << 20;
constexpr std::size_t maxColumns = 1024;

std::optional<double> parseNumber(std::string_view field) {
  double v = 0;
  bool integer = false;
  if (!isph::parseNumber(field, v, integer)) return std::nullopt;
  return v;
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

class CsvParser {
 public:
  CsvParser(std::string_view text, const std::string& fileName)
      : text_(text), name_(std::make_shared<const std::string>(fileName)) {}

  CsvPoints parse() {
    CsvPoints out;
    for (int number = 1; nextLine(number); ++number) {
      const std::string_view content = trim(line_);
      if (content.empty() || content.front() == '#') continue;
      const std::vector<std::string_view> fields = splitFields(number);
      if (first_) {
        first_ = false;
        if (readHeader(fields, number, content)) continue;
      }
      const std::size_t needed = std::max(xColumn_, yColumn_) + 1;
      if (fields.size() < needed) {
        fatalIOError(
            at(number),
            fmt::format("expected x,y values (at least {} comma-separated fields), found \"{}\"",
                        needed, std::string(content)));
      }
      const double x = coordinate(fields[xColumn_], "x", number);
      const double y = coordinate(fields[yColumn_], "y", number);
      out.points.emplace_back(x, y);
      out.lines.push_back(number);
    }
    if (out.points.empty()) fatalIOError(at(0), "the CSV file holds no points");
    return out;
  }

 private:
  SourceLocation at(int line) const { return SourceLocation{name_, line, 0}; }

  // The next line (without its end of line) in line_; false at the end of the text.
  bool nextLine(int number) {
    if (pos_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    line_ = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
    if (line_.size() > maxLineBytes) {
      fatalIOError(at(number),
                   fmt::format("the line is longer than {} KiB: not a CSV file of points?",
                               maxLineBytes >> 10));
    }
    return true;
  }

  std::vector<std::string_view> splitFields(int number) const {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line_.find(',', start);
      fields.push_back(trim(line_.substr(start, comma - start)));
      if (comma == std::string_view::npos) break;
      if (fields.size() >= maxColumns) {
        fatalIOError(at(number),
                     fmt::format("the line has more than {} columns: not a CSV file of points?",
                                 maxColumns));
      }
      start = comma + 1;
    }
    return fields;
  }

  // A first line with a field that is no number names the columns: true if it was one.
  bool readHeader(const std::vector<std::string_view>& fields, int number,
                  std::string_view content) {
    const bool header = std::any_of(fields.begin(), fields.end(), [](std::string_view f) {
      return !parseNumber(f) && !isNonFiniteNumber(f);
    });
    if (!header) return false;
    std::vector<std::string> names;
    for (const auto f : fields) names.push_back(lower(f));
    const auto xi = std::find(names.begin(), names.end(), "x");
    const auto yi = std::find(names.begin(), names.end(), "y");
    if (xi == names.end() || yi == names.end()) {
      fatalIOError(
          at(number),
          fmt::format("the header line of a point file must name columns x and y; found: {}",
                      std::string(content)));
    }
    xColumn_ = static_cast<std::size_t>(xi - names.begin());
    yColumn_ = static_cast<std::size_t>(yi - names.begin());
    return true;
  }

  double coordinate(std::string_view field, const char* column, int number) const {
    if (const auto v = parseNumber(field)) return *v;
    if (isNonFiniteNumber(field)) {
      fatalIOError(at(number),
                   fmt::format("{} = '{}' is not a finite number", column, std::string(field)));
    }
    fatalIOError(at(number),
                 fmt::format("expected a number for {}, found \"{}\"", column, std::string(field)));
  }

  std::string_view text_;
  std::shared_ptr<const std::string> name_;
  std::size_t pos_ = 0;
  std::string_view line_;
  bool first_ = true;
  std::size_t xColumn_ = 0, yColumn_ = 1;
};

}  // namespace

CsvPoints parseCsvPoints(std::string_view text, const std::string& fileName) {
  return CsvParser(text, fileName).parse();
}

CsvPoints readCsvPoints(const std::filesystem::path& file, const SourceLocation& namedAt) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    fatalIOError(namedAt, fmt::format("cannot read the CSV file {} (no such file)", file.string()));
  }
  std::string text;
  try {
    text = readWholeFile(file, maxFileBytes, "a CSV file of points");
  } catch (
      const FatalError& e) {  // unreadable, not a regular file, too large: said where it is named
    fatalIOError(namedAt, e.what());
  }
  return parseCsvPoints(text, file.string());
}

}  // namespace isph
