// Time names (OpenFOAM's general format), listing time directories, finding a time.
#include <gtest/gtest.h>

#include "TimeTestHelpers.hpp"
#include "core/time/TimeName.hpp"

namespace isph {
namespace {

TEST(TimeName, GeneralFormat) {
  EXPECT_EQ(timeName(0), "0");
  EXPECT_EQ(timeName(-0.0), "0");
  EXPECT_EQ(timeName(0.1), "0.1");
  EXPECT_EQ(timeName(1e-05), "1e-05");
  EXPECT_EQ(timeName(100), "100");
  EXPECT_EQ(timeName(2.5), "2.5");
  EXPECT_EQ(timeName(1234567), "1.23457e+06");
  EXPECT_EQ(timeName(-0.5), "-0.5");
}

TEST(TimeName, RoundOffDisappears) {
  EXPECT_EQ(timeName(0.1 + 0.2), "0.3");
  EXPECT_EQ(timeName(0.7 * 3), "2.1");
}

TEST(TimeName, Precision) {
  EXPECT_EQ(timeName(1.0 / 3, 3), "0.333");
  EXPECT_EQ(timeName(1.0 / 3, 8), "0.33333333");
  EXPECT_EQ(timeName(0.12345678, 8), "0.12345678");
  EXPECT_EQ(timeName(0.1 + 0.2, 8), "0.3");
  EXPECT_EQ(timeName(0.1 + 0.2, 17), "0.30000000000000004");
  EXPECT_EQ(timeName(0.0123456, 3), "0.0123");
}

TEST(TimeName, ParseTimeName) {
  double v = -1;
  EXPECT_TRUE(parseTimeName("0.1", v));
  EXPECT_DOUBLE_EQ(v, 0.1);
  EXPECT_TRUE(parseTimeName("1e-05", v));
  EXPECT_DOUBLE_EQ(v, 1e-05);
  EXPECT_FALSE(parseTimeName("", v));
  EXPECT_FALSE(parseTimeName("0.orig", v));
  EXPECT_FALSE(parseTimeName("constant", v));
  EXPECT_FALSE(parseTimeName("inf", v));
  EXPECT_FALSE(parseTimeName("nan", v));
  EXPECT_FALSE(parseTimeName("1 ", v));
}

TEST(TimeName, ListTimesSortsAndIgnoresNonTimes) {
  test::TempCase c;
  for (const char* d : {"0", "0.1", "1e-05", "2", "0.25", "constant", "system", "0.orig",
                        ".0.1.tmp.123", ".0.3.old.77", "VTK", "postProcessing"}) {
    c.mkdir(d);
  }
  c.write("3", "a file, not a time directory\n");
  const auto times = listTimes(c.path());
  ASSERT_EQ(times.size(), 5u);
  const std::vector<std::string> names{"0", "1e-05", "0.1", "0.25", "2"};
  for (std::size_t k = 0; k < names.size(); ++k) EXPECT_EQ(times[k].name, names[k]);
  EXPECT_DOUBLE_EQ(times[1].value, 1e-05);
  EXPECT_DOUBLE_EQ(times[4].value, 2);
}

TEST(TimeName, ListTimesOfMissingCaseIsEmpty) {
  EXPECT_TRUE(listTimes("/nonexistent/isph/case").empty());
}

TEST(TimeName, FindTime) {
  const std::vector<Instant> times{{0, "0"}, {0.1, "0.1"}, {0.333333, "0.333333"}, {1, "1"}};
  const Instant* t = findTime(times, 0.1);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->name, "0.1");
  t = findTime(times, 0.3333332);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->name, "0.333333");
  EXPECT_EQ(findTime(times, 0.33), nullptr);
  ASSERT_NE(findTime(times, 0.0), nullptr);
  EXPECT_EQ(findTime(times, 0.0)->name, "0");
  EXPECT_EQ(findTime(times, 1e-9), nullptr);
  EXPECT_EQ(findTime({}, 0.0), nullptr);
  EXPECT_EQ(findTime(times, 0.33, 0.1)->name, "0.333333");
}

}  // namespace
}  // namespace isph
