#include "postProcessing/forces/ForceFigures.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

ForceFigures forceFigures(const std::vector<double>& t, const std::vector<double>& raw,
                          const std::vector<double>& filtered, double lateForceWindow) {
  if (t.empty() || raw.size() != t.size() || filtered.size() != t.size()) {
    fatalError(fmt::format("force figures: {} times, {} raw and {} filtered values; expected one of each, at least "
                           "one",
                           t.size(), raw.size(), filtered.size()));
  }
  if (!(lateForceWindow > 0)) {
    fatalError(fmt::format("force figures: late force window {} s; expected a positive duration", lateForceWindow));
  }
  ForceFigures f;
  f.filteredPeak = filtered[0], f.filteredPeakTime = t[0];
  f.rawMax = raw[0], f.rawMaxTime = t[0];
  for (std::size_t k = 1; k < t.size(); ++k) {
    if (filtered[k] > f.filteredPeak) f.filteredPeak = filtered[k], f.filteredPeakTime = t[k];
    if (raw[k] > f.rawMax) f.rawMax = raw[k], f.rawMaxTime = t[k];
  }
  f.lateTo = t.back();
  f.lateFrom = std::max(t.front(), t.back() - lateForceWindow);
  f.lateForce = CentredMovingAverage::mean(t, filtered, f.lateFrom, f.lateTo);
  return f;
}

std::string forceFiguresText(const ForceFigures& f, const std::string& what, const std::string& unit,
                             const CentredMovingAverage& filter, double lateForceWindow) {
  std::string s = fmt::format("# Figures of {}, from its trace filtered by a {}.\n", what, filter.describe());
  s += fmt::format("# filteredPeak: the filtered trace's largest value (the figure to design for); lateForce: the "
                   "filtered trace's time mean over the last {:g} s ({:.6g} to {:.6g} s); rawMax: the unfiltered "
                   "largest value, reported, not a design figure\n",
                   lateForceWindow, f.lateFrom, f.lateTo);
  s += fmt::format("filterWindow {:g} s\n", filter.window());
  s += fmt::format("filteredPeak {:.6g} {}\n", f.filteredPeak, unit);
  s += fmt::format("filteredPeakTime {:.6g} s\n", f.filteredPeakTime);
  s += fmt::format("lateForceWindow {:g} s\n", lateForceWindow);
  s += fmt::format("lateForce {:.6g} {}\n", f.lateForce, unit);
  s += fmt::format("rawMax {:.6g} {}\n", f.rawMax, unit);
  s += fmt::format("rawMaxTime {:.6g} s\n", f.rawMaxTime);
  return s;
}

}  // namespace isph
