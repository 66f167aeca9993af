#pragma once
// Beside a set's raw force history, the history a designer reads (issue 49): every force and
// moment column filtered by the set's centred moving average (`filterWindow`, default 0.01 s;
// CentredMovingAverage.hpp), and the figures of its force normal to the patches, Fn: the
// filtered peak and its time, the late force over the last `lateForceWindow` seconds and the
// raw maximum (ForceFigures.hpp). Written by the patchForces function object
// (postProcessing/<name>/<startTime>/forceFiltered.dat and forceFigures.txt) and sampleForces
// (postProcessing/sampleForces/<firstTime>/<set>Filtered.dat and <set>Figures.txt).
//
// The filtered table has the raw table's columns and header (ForceTable.hpp), under a first
// comment line that names the filter; Time and nWall are copied as they are.
#include <filesystem>
#include <string>
#include <vector>

#include "postProcessing/forces/ForceFigures.hpp"
#include "postProcessing/forces/ForceSet.hpp"
#include "postProcessing/forces/ForceTable.hpp"

namespace isph {

// The rows of a force table, one vector of its columns per time (ForceTable's order).
using ForceRows = std::vector<std::vector<double>>;

// The numbers of a force table's rows in `text` (comment and empty lines skipped).
ForceRows readForceRows(const std::string& text);

struct FilteredForces {
  ForceRows rows;        // the filtered table
  ForceFigures figures;  // of its column Fn
};

// Every column of `rows` but Time and nWall filtered, and the figures of Fn. FatalError when
// a row's length is not the table's or there is no row.
FilteredForces filterForces(const ForceSet& set, const ForceTable& table, const ForceRows& rows);

// The filtered table's text: a comment line naming the filter, then `rawHeader` (the raw
// table's comment lines, ForceTable::header), then the rows.
std::string filteredForceText(const ForceSet& set, const ForceTable& table, const std::string& rawHeader,
                              const ForceRows& filtered);

// Filters `rows` and writes the filtered table and the figures, each replaced atomically.
// Returns the figures.
ForceFigures writeFilteredForces(const ForceSet& set, const ForceTable& table, const std::string& rawHeader,
                                 const ForceRows& rows, const std::filesystem::path& filteredFile,
                                 const std::filesystem::path& figuresFile);

}  // namespace isph
