// The centred moving average of a force history (issue 49): a constant and a straight line
// pass unchanged away from the ends, a one-step spike is spread over the window (its impulse
// kept), uneven steps weigh by their length, a 30 Hz ringing is damped by sin(pi f W)/(pi f W),
// and the ends are means over the part of the window inside the trace.
#include "postProcessing/forces/CentredMovingAverage.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/Error.hpp"

namespace isph {
namespace {

std::vector<double> times(int n, double dt) {
  std::vector<double> t(n);
  for (int k = 0; k < n; ++k) t[k] = k * dt;
  return t;
}

TEST(CentredMovingAverage, KeepsAConstantAndAStraightLineAwayFromTheEnds) {
  const auto t = times(201, 0.001);
  std::vector<double> c(t.size(), 7.0), line(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) line[k] = 3 + 50 * t[k];
  const CentredMovingAverage filter(0.01);
  const auto fc = filter.apply(t, c);
  const auto fl = filter.apply(t, line);
  for (std::size_t k = 0; k < t.size(); ++k) {
    EXPECT_NEAR(fc[k], 7.0, 1e-12);
    if (k >= 5 && k + 5 < t.size()) {
      EXPECT_NEAR(fl[k], line[k], 1e-9) << "t = " << t[k];
    }
  }
  // At the first sample the window is [0, 0.005]: the mean of the line there.
  EXPECT_NEAR(fl[0], 3 + 50 * 0.0025, 1e-9);
  EXPECT_NEAR(fl.back(), 3 + 50 * (0.2 - 0.0025), 1e-9);
}

// A spike of one sample, 100 N at 1 ms steps: a triangle of impulse 0.1 N s; over 10 ms it
// reads 10 N at its centre.
TEST(CentredMovingAverage, SpreadsAOneStepSpikeOverTheWindowKeepingItsImpulse) {
  const auto t = times(101, 0.001);
  std::vector<double> v(t.size(), 0.0);
  v[50] = 100;
  const auto f = CentredMovingAverage(0.01).apply(t, v);
  EXPECT_NEAR(f[50], 10.0, 1e-9);
  double impulse = 0;
  for (std::size_t k = 1; k < t.size(); ++k) impulse += 0.5 * (f[k] + f[k - 1]) * (t[k] - t[k - 1]);
  EXPECT_NEAR(impulse, 0.1, 1e-9);
}

// Uneven steps: the mean is in time, not over the samples. A step from 0 to 1 at t = 0.5
// sampled densely after it: the mean over [0.45, 0.55] is one half whatever the count.
TEST(CentredMovingAverage, WeighsUnevenStepsByTheirLength) {
  std::vector<double> t{0.0, 0.4, 0.5, 0.5};
  std::vector<double> v{0.0, 0.0, 0.0, 1.0};
  for (int k = 1; k <= 100; ++k) t.push_back(0.5 + 0.001 * k), v.push_back(1.0);
  t.push_back(1.0), v.push_back(1.0);
  EXPECT_NEAR(CentredMovingAverage::mean(t, v, 0.45, 0.55), 0.5, 1e-12);
  EXPECT_NEAR(CentredMovingAverage::mean(t, v, 0.2, 0.3), 0.0, 1e-12);
  EXPECT_NEAR(CentredMovingAverage::mean(t, v, -1, 0.5), 0.0, 1e-12) << "cut to the trace";
  EXPECT_NEAR(CentredMovingAverage::mean(t, v, 0.7, 0.7), 1.0, 1e-12) << "no length: the sample there";
}

TEST(CentredMovingAverage, DampsARingingAsABoxWindow) {
  const double f = 30, W = 0.01;
  const auto t = times(2001, 0.0001);
  std::vector<double> v(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) v[k] = std::sin(2 * M_PI * f * t[k]);
  const auto out = CentredMovingAverage(W).apply(t, v);
  double peak = 0;
  for (std::size_t k = 200; k + 200 < t.size(); ++k) peak = std::max(peak, std::abs(out[k]));
  const double gain = std::sin(M_PI * f * W) / (M_PI * f * W);  // 0.858
  EXPECT_NEAR(peak, gain, 1e-3);
}

TEST(CentredMovingAverage, RefusesABadWindowOrTrace) {
  EXPECT_THROW(CentredMovingAverage(0), FatalError);
  EXPECT_THROW(CentredMovingAverage(-0.01), FatalError);
  EXPECT_THROW(CentredMovingAverage(NAN), FatalError);
  const CentredMovingAverage filter(0.01);
  EXPECT_THROW(filter.apply({0, 1}, {1}), FatalError);
  EXPECT_THROW(filter.apply({0, 1, 0.5}, {1, 2, 3}), FatalError) << "time goes back";
  EXPECT_TRUE(filter.apply({}, {}).empty());
  EXPECT_NE(filter.describe().find("centred moving average over 0.01 s"), std::string::npos);
}

}  // namespace
}  // namespace isph
