#pragma once
// `sampleForces -plot`: a PNG of a set's force normal to its patches against time (total,
// pressure and deviatoric parts), with the set's reference CSV overlaid as points when it
// names one. Drawn by gnuplot (pngcairo terminal), run as a child process; the PNG is
// written under a temporary name and renamed, as every output file.
#include <filesystem>

#include "postProcessing/forces/ForceSet.hpp"
#include "postProcessing/forces/ForceTable.hpp"

namespace isph {

// Whether a `gnuplot` executable is on PATH.
bool gnuplotAvailable();

struct ForcePlotFiles {
  std::filesystem::path dat;        // the set's force history
  std::filesystem::path png;        // the image to write
  std::filesystem::path reference;  // the reference CSV (empty: none)
};

// The gnuplot script that draws `files.png` (exposed for tests).
std::string forcePlotScript(const ForceSet& set, const ForceTable& table, const ForcePlotFiles& files);

// Draws the PNG. FatalError when gnuplot is not installed (saying so, and how to install it),
// when the reference CSV does not exist, or when gnuplot fails.
void plotForces(const ForceSet& set, const ForceTable& table, const ForcePlotFiles& files);

}  // namespace isph
