#include "postProcessing/forces/CentredMovingAverage.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/Error.hpp"

namespace isph {

namespace {

// The trace's running integral at its samples: I[k] = ∫ v dt from t[0] to t[k] (trapezoids).
std::vector<double> runningIntegral(const std::vector<double>& t, const std::vector<double>& v) {
  std::vector<double> I(t.size(), 0.0);
  for (std::size_t k = 1; k < t.size(); ++k) I[k] = I[k - 1] + 0.5 * (t[k] - t[k - 1]) * (v[k] + v[k - 1]);
  return I;
}

// ∫ v dt from t[0] to s (t[0] <= s <= t.back()), from the running integral.
double integralTo(const std::vector<double>& t, const std::vector<double>& v, const std::vector<double>& I, double s) {
  auto k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), s) - t.begin());
  if (k == 0) return 0.0;
  if (k == t.size()) return I.back();
  --k;  // t[k] <= s < t[k + 1]
  const double h = t[k + 1] - t[k];
  const double vs = h > 0 ? v[k] + (v[k + 1] - v[k]) * (s - t[k]) / h : v[k];
  return I[k] + 0.5 * (s - t[k]) * (v[k] + vs);
}

double meanFrom(const std::vector<double>& t, const std::vector<double>& v, const std::vector<double>& I, double from,
                double to) {
  const double a = std::max(from, t.front()), b = std::min(to, t.back());
  if (!(b > a)) {  // no length: the sample nearest the interval's middle
    const double m = std::clamp(0.5 * (from + to), t.front(), t.back());
    const auto it = std::lower_bound(t.begin(), t.end(), m);
    auto k = static_cast<std::size_t>(it - t.begin());
    if (k == t.size() || (k > 0 && m - t[k - 1] < t[k] - m)) --k;
    return v[k];
  }
  return (integralTo(t, v, I, b) - integralTo(t, v, I, a)) / (b - a);
}

void checkTrace(const std::vector<double>& t, const std::vector<double>& v) {
  if (t.size() != v.size()) {
    fatalError(fmt::format("moving average: {} times for {} values", t.size(), v.size()));
  }
  for (std::size_t k = 1; k < t.size(); ++k) {
    if (t[k] < t[k - 1]) {
      fatalError(fmt::format("moving average: the times decrease ({} after {}); expected a history in time order",
                             t[k], t[k - 1]));
    }
  }
}

}  // namespace

CentredMovingAverage::CentredMovingAverage(double window) : window_(window) {
  if (!(window > 0) || !std::isfinite(window)) {
    fatalError(fmt::format("moving average: window {} s; expected a positive duration", window));
  }
}

std::string CentredMovingAverage::describe() const {
  return fmt::format("centred moving average over {:g} s (a box window, the trace's time mean over t +- {:g} s; "
                     "cut to the trace at its ends)",
                     window_, 0.5 * window_);
}

std::vector<double> CentredMovingAverage::apply(const std::vector<double>& t, const std::vector<double>& v) const {
  checkTrace(t, v);
  if (t.empty()) return {};
  const std::vector<double> I = runningIntegral(t, v);
  std::vector<double> out(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) out[k] = meanFrom(t, v, I, t[k] - 0.5 * window_, t[k] + 0.5 * window_);
  return out;
}

double CentredMovingAverage::mean(const std::vector<double>& t, const std::vector<double>& v, double from, double to) {
  checkTrace(t, v);
  if (t.empty()) return std::numeric_limits<double>::quiet_NaN();
  return meanFrom(t, v, runningIntegral(t, v), from, to);
}

}  // namespace isph
