// Progress arithmetic: fraction of the run, the rate over the recent window, time left, the
// status line and the formatting of durations.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/time/RunProgress.hpp"

namespace isph {
namespace {

TEST(RunProgress, FractionIsRelativeToTheStartTime) {
  RunProgress p(0, 0.5);  // a restart from t = 0.5
  EXPECT_DOUBLE_EQ(p.fraction(2.5), 0);
  p.advance(1, 1.0);
  EXPECT_DOUBLE_EQ(p.fraction(2.5), 0.25);
  p.advance(2, 3.0);
  EXPECT_DOUBLE_EQ(p.fraction(2.5), 1);  // past endTime: clamped
  EXPECT_DOUBLE_EQ(p.fraction(0.5), 1);  // nothing to do
  EXPECT_TRUE(p.finished(2.5));
  RunProgress before(0, 1.0);
  before.advance(1, 0.9);
  EXPECT_DOUBLE_EQ(before.fraction(2), 0);  // before the start: clamped
}

TEST(RunProgress, TimeLeftAtAConstantRate) {
  RunProgress p(100, 0);  // wall clock starts at 100 s
  for (int s = 1; s <= 50; ++s) p.advance(100 + s, 0.01 * s);
  EXPECT_DOUBLE_EQ(p.wallSeconds(), 50);
  ASSERT_TRUE(p.rate());
  EXPECT_NEAR(*p.rate(), 0.01, 1e-12);
  ASSERT_TRUE(p.secondsLeft(1.0));
  EXPECT_NEAR(*p.secondsLeft(1.0), 50, 1e-9);
}

TEST(RunProgress, RateFollowsTheLastWindowNotTheWholeRun) {
  RunProgress p(0, 0, 30);
  double t = 0;
  for (int s = 1; s <= 40; ++s) p.advance(s, t += 0.01);    // fast start
  for (int s = 41; s <= 80; ++s) p.advance(s, t += 0.002);  // then five times slower
  ASSERT_TRUE(p.rate());
  // Since the start it would be 0.48 / 80 = 0.006.
  EXPECT_NEAR(*p.rate(), 0.002, 1e-12);
  EXPECT_NEAR(*p.secondsLeft(1.0), (1.0 - 0.48) / 0.002, 1e-6);
}

TEST(RunProgress, WindowCoversTheWholeRunWhileShorter) {
  RunProgress p(0, 0, 30);
  p.advance(10, 0.3);   // fast
  p.advance(20, 0.35);  // slow
  EXPECT_NEAR(*p.rate(), 0.35 / 20, 1e-12);
}

TEST(RunProgress, RateUnknownWithoutProgress) {
  RunProgress p(5, 0);
  EXPECT_FALSE(p.rate());
  EXPECT_FALSE(p.secondsLeft(1));
  p.advance(5, 0.1);  // no wall time yet
  EXPECT_FALSE(p.rate());
  RunProgress stuck(5, 0);
  stuck.advance(6, 0.0);  // no simulated time
  EXPECT_FALSE(stuck.rate());
  EXPECT_EQ(stuck.statusLine("app", 1), "app  t = 0 s / 1 s (0%)  wall 0:01");
}

TEST(RunProgress, StatusLine) {
  RunProgress p(0, 0);
  p.advance(41, 0.452);
  // left: 2.048 s at 0.452 / 41 s per second = 185.8 s
  EXPECT_EQ(p.statusLine("isphLandslideFoam", 2.5),
            "isphLandslideFoam  t = 0.452 s / 2.5 s (18%)  wall 0:41  left ~3:05");
  EXPECT_EQ(p.statusLine("isphLandslideFoam", 2.5, "stopped"),
            "isphLandslideFoam  t = 0.452 s / 2.5 s (18%)  wall 0:41  stopped");
}

TEST(RunProgress, PercentRoundsDown) {
  RunProgress p(0, 0);
  p.advance(1, 0.999);
  EXPECT_NE(p.statusLine("a", 1).find("(99%)"), std::string::npos) << p.statusLine("a", 1);
  p.advance(2, 1.0);
  EXPECT_NE(p.statusLine("a", 1).find("(100%)  wall 0:02  left ~0:00"), std::string::npos)
      << p.statusLine("a", 1);
}

TEST(RunProgress, FormatDuration) {
  EXPECT_EQ(RunProgress::formatDuration(0), "0:00");
  EXPECT_EQ(RunProgress::formatDuration(41.9), "0:41");
  EXPECT_EQ(RunProgress::formatDuration(185.77), "3:05");
  EXPECT_EQ(RunProgress::formatDuration(3599.5), "59:59");
  EXPECT_EQ(RunProgress::formatDuration(3723), "1:02:03");
  EXPECT_EQ(RunProgress::formatDuration(100 * 3600), "100:00:00");
  EXPECT_EQ(RunProgress::formatDuration(-1), "?");
  EXPECT_EQ(RunProgress::formatDuration(std::nan("")), "?");
  EXPECT_EQ(RunProgress::formatDuration(std::numeric_limits<double>::infinity()), "?");
  EXPECT_EQ(RunProgress::formatDuration(1e30), "?");
}

}  // namespace
}  // namespace isph
