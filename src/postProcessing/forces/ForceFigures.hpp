#pragma once
// The figures a designer reads off a force history (issue 49): from the trace filtered by a
// centred moving average (CentredMovingAverage.hpp), the peak and its time and the late
// (deposit) force, the filtered trace's time mean over the last `lateForceWindow` seconds; the
// raw maximum and its time beside them, reported, never the headline (single particles striking
// a wall make it a spike of one step).
//
// Written as forceFigures.txt (the function object) or <set>Figures.txt (sampleForces), one
// "name value unit" line each, as a case's results.txt:
//   filteredPeak 1346 N / filteredPeakTime 0.861 s / lateForce 168 N / rawMax 3249 N / ...
#include <string>
#include <vector>

#include "postProcessing/forces/CentredMovingAverage.hpp"

namespace isph {

struct ForceFigures {
  double filteredPeak = 0;
  double filteredPeakTime = 0;
  double lateForce = 0;      // mean of the filtered trace over [lateFrom, lateTo]
  double lateFrom = 0;
  double lateTo = 0;
  double rawMax = 0;
  double rawMaxTime = 0;
};

// From the samples `t` of the raw trace `raw` and its filtered trace `filtered` (same length,
// at least one sample). FatalError for lengths that differ, an empty trace or a late window
// that is not positive.
ForceFigures forceFigures(const std::vector<double>& t, const std::vector<double>& raw,
                          const std::vector<double>& filtered, double lateForceWindow);

// The lines of forceFigures.txt: comment lines naming `what` (the set and its column), the
// filter and the late window, then the figures in `unit` (N, or N/m per metre of width).
std::string forceFiguresText(const ForceFigures& f, const std::string& what, const std::string& unit,
                             const CentredMovingAverage& filter, double lateForceWindow);

}  // namespace isph
