#include "postProcessing/forces/ForcePlot.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/Error.hpp"
#include "core/io/ReadFile.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/StagingNames.hpp"

namespace isph {

namespace {

// A gnuplot single-quoted string ('' stands for a quote inside).
std::string quoted(const std::filesystem::path& p) {
  std::string out = "'";
  for (const char c : p.string()) {
    out += c;
    if (c == '\'') out += '\'';
  }
  return out + "'";
}

// How to read the reference CSV: its separator and whether its first line is a header.
struct CsvLayout {
  bool comma = true;
  bool header = false;
};

CsvLayout csvLayout(const std::filesystem::path& file) {
  std::istringstream in(readFileBytes(file, 64 * 1024));  // the first lines are enough
  std::string line;
  while (std::getline(in, line) && (line.empty() || line[0] == '#')) {
  }
  CsvLayout layout;
  layout.comma = line.find(',') != std::string::npos;
  std::istringstream first(layout.comma ? line.substr(0, line.find(',')) : line);
  double value = 0;
  layout.header = !(first >> value);
  return layout;
}

// A POSIX shell single-quoted word.
std::string shellQuoted(const std::filesystem::path& p) {
  std::string out = "'";
  for (const char c : p.string()) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

bool gnuplotAvailable() { return std::system("command -v gnuplot > /dev/null 2>&1") == 0; }

std::string forcePlotScript(const ForceSet& set, const ForceTable& table, const ForcePlotFiles& files) {
  const std::string unit = table.columns()[1].unit;
  std::string s;
  s += "set terminal pngcairo size 1000,640 enhanced font ',11'\n";
  s += fmt::format("set output {}\n", quoted(files.png));
  s += fmt::format("set title \"Force on set {} (normal to the patches)\" noenhanced\n", set.name);
  s += "set xlabel 'Time [s]'\n";
  s += fmt::format("set ylabel 'Force [{}]'\n", unit);
  s += "set grid\nset key top left\nset datafile commentschars '#'\n";
  const int t = table.column("Time");
  s += fmt::format("plot {0} using {1}:{2} with lines lw 2 title 'total F_n', \\\n"
                   "     {0} using {1}:{3} with lines dt 2 title 'pressure F_{{p,n}}', \\\n"
                   "     {0} using {1}:{4} with lines dt 3 title 'deviatoric F_{{d,n}}'",
                   quoted(files.dat), t, table.column("Fn"), table.column("Fpn"), table.column("Fdn"));
  if (!files.reference.empty()) {
    const CsvLayout layout = csvLayout(files.reference);
    s += fmt::format(", \\\n     {} {}using {}:{} with points pt 7 ps 0.8 title 'reference'",
                     quoted(files.reference), layout.header ? "skip 1 " : "", set.referenceColumns[0],
                     set.referenceColumns[1]);
    // Separators are global in gnuplot: tabs (the .dat) or commas (the CSV), one at a time.
    if (layout.comma) s.insert(s.find("plot "), "set datafile separator \"\\t,\"\n");
  }
  return s + "\n";
}

void plotForces(const ForceSet& set, const ForceTable& table, const ForcePlotFiles& files) {
  if (!gnuplotAvailable()) {
    fatalError(fmt::format("-plot: gnuplot is not installed, so {} cannot be drawn\n    (install it with "
                           "`sudo apt-get install gnuplot-nox`; the force history {} is written)",
                           files.png.string(), files.dat.string()));
  }
  if (!files.reference.empty() && !std::filesystem::is_regular_file(files.reference)) {
    fatalIOError(set.where, fmt::format("set '{}': the reference file {} (keyword 'reference') does not exist",
                                        set.name, files.reference.string()));
  }
  // gnuplot draws into a hidden temporary file, renamed over the PNG once complete.
  const auto tmpPng = stagingName(files.png, "tmp");
  ForcePlotFiles staged = files;
  staged.png = tmpPng;
  const auto script = stagingName(files.png.parent_path() / (set.name + ".gnuplot"), "tmp");
  {
    std::ofstream out(script);
    out << forcePlotScript(set, table, staged);
  }
  const std::string command = fmt::format("gnuplot {} 2>&1", shellQuoted(script));
  const int rc = std::system(command.c_str());
  std::filesystem::remove(script);
  if (rc != 0 || !std::filesystem::is_regular_file(tmpPng)) {
    std::filesystem::remove(tmpPng);
    fatalError(fmt::format("-plot: gnuplot failed (status {}) drawing {}", rc, files.png.string()));
  }
  std::filesystem::rename(tmpPng, files.png);
}

}  // namespace isph
