#pragma once
// A centred moving average of a sampled trace (a force history): each sample replaced by the
// mean of the trace over the window [t − W/2, t + W/2] around it, about what a load cell of
// bandwidth ~1/W records. The trace is taken as piecewise linear between its samples and the
// mean is its integral over the window divided by the window's length (trapezoidal, so the
// uneven steps of an adjustable time step weigh by their length, not by their count). At the
// ends of the trace the window is cut to the part inside it (the first and last W/2 are means
// over less than W). Samples closer than W carry the filter; a window shorter than the spacing
// of the samples returns the trace nearly as it is (sampleForces on written times says so).
#include <string>
#include <vector>

namespace isph {

class CentredMovingAverage {
 public:
  // FatalError for a window that is not positive and finite [s].
  explicit CentredMovingAverage(double window);

  double window() const { return window_; }
  // The shape, for the files that hold a filtered trace: "centred moving average over 0.01 s ...".
  std::string describe() const;

  // The filtered trace at the samples `t` (increasing; equal neighbours allowed) of `v`.
  // FatalError when the lengths differ or t decreases.
  std::vector<double> apply(const std::vector<double>& t, const std::vector<double>& v) const;

  // The mean of the piecewise-linear trace over [from, to] cut to [t.front(), t.back()]; the
  // value at the nearest sample when that interval has no length. NaN for an empty trace.
  static double mean(const std::vector<double>& t, const std::vector<double>& v, double from, double to);

 private:
  double window_;
};

}  // namespace isph
