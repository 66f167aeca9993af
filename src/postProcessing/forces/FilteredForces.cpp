#include "postProcessing/forces/FilteredForces.hpp"

#include <fmt/format.h>

#include <iterator>
#include <sstream>

#include "core/Error.hpp"
#include "core/io/AtomicFile.hpp"

namespace isph {

ForceRows readForceRows(const std::string& text) {
  ForceRows rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    std::vector<double> v;
    for (double x; row >> x;) v.push_back(x);
    if (!v.empty()) rows.push_back(std::move(v));
  }
  return rows;
}

FilteredForces filterForces(const ForceSet& set, const ForceTable& table, const ForceRows& rows) {
  const std::size_t nCols = table.columns().size();
  if (rows.empty()) fatalError(fmt::format("set '{}': no force row to filter", set.name));
  for (const auto& r : rows) {
    if (r.size() != nCols) {
      fatalError(fmt::format("set '{}': a force row of {} columns at time {}; expected the table's {}", set.name,
                             r.size(), r.empty() ? 0.0 : r[0], nCols));
    }
  }
  const CentredMovingAverage filter(set.filterWindow);
  const std::size_t time = static_cast<std::size_t>(table.column("Time") - 1);
  const std::size_t nWall = static_cast<std::size_t>(table.column("nWall") - 1);
  const std::size_t fn = static_cast<std::size_t>(table.column("Fn") - 1);
  std::vector<double> t(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) t[k] = rows[k][time];

  FilteredForces out;
  out.rows = rows;
  std::vector<double> column(rows.size()), rawFn;
  for (std::size_t c = 0; c < nCols; ++c) {
    if (c == time || c == nWall) continue;
    for (std::size_t k = 0; k < rows.size(); ++k) column[k] = rows[k][c];
    if (c == fn) rawFn = column;
    const std::vector<double> filtered = filter.apply(t, column);
    for (std::size_t k = 0; k < rows.size(); ++k) out.rows[k][c] = filtered[k];
  }
  std::vector<double> filteredFn(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) filteredFn[k] = out.rows[k][fn];
  out.figures = forceFigures(t, rawFn, filteredFn, set.lateForceWindow);
  return out;
}

std::string filteredForceText(const ForceSet& set, const ForceTable& table, const std::string& rawHeader,
                              const ForceRows& filtered) {
  std::string s = fmt::format("# Filtered: every force and moment column below is the {} of the raw history "
                              "(Time and nWall as they are)\n",
                              CentredMovingAverage(set.filterWindow).describe());
  s += rawHeader;
  const std::size_t nWall = static_cast<std::size_t>(table.column("nWall") - 1);
  // (formatted in place: the whole table is rewritten at every write time of a run, and a string
  // per number was half of the function objects' time in the barrier's)
  auto out = std::back_inserter(s);
  for (const auto& r : filtered) {
    for (std::size_t c = 0; c < r.size(); ++c) {
      const double v = r[c] == 0 ? 0.0 : r[c];  // no "-0"
      if (c == nWall) {
        fmt::format_to(out, "\t{:.0f}", v);
      } else {
        fmt::format_to(out, "{}{:.8g}", c ? "\t" : "", v);
      }
    }
    s += '\n';
  }
  return s;
}

ForceFigures writeFilteredForces(const ForceSet& set, const ForceTable& table, const std::string& rawHeader,
                                 const ForceRows& rows, const std::filesystem::path& filteredFile,
                                 const std::filesystem::path& figuresFile) {
  const FilteredForces f = filterForces(set, table, rows);
  writeFileAtomic(filteredFile, filteredForceText(set, table, rawHeader, f.rows));
  const std::string what = fmt::format("set '{}': Fn, its force normal to the patches, positive into the structure",
                                       set.name);
  writeFileAtomic(figuresFile, forceFiguresText(f.figures, what, table.columns()[1].unit,
                                                CentredMovingAverage(set.filterWindow), set.lateForceWindow));
  return f.figures;
}

}  // namespace isph
