#pragma once
// Helpers shared by the function-object tests: a controlDict `functions` dictionary from
// text, and the data rows of a function object's output file as numbers.
#include <sstream>
#include <string>
#include <vector>

#include "../PostProcessingTestHelpers.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph::pptest {

// The rows of a table file that are not comments (`#`), as numbers.
inline std::vector<std::vector<double>> dataRows(const std::filesystem::path& file) {
  std::vector<std::vector<double>> out;
  std::istringstream in(readText(file));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    out.emplace_back();
    for (double v; row >> v;) out.back().push_back(v);
  }
  return out;
}

// `functions { <text> }` as system/controlDict would hold it.
inline Dictionary functionsDict(const std::string& text) {
  return Dictionary::parse("functions {\n" + text + "\n}\n", "system/controlDict").subDict("functions");
}

}  // namespace isph::pptest
