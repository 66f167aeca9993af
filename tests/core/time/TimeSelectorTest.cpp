// -time RANGES, -latestTime and -noZero, as OpenFOAM's timeSelector.
#include <gtest/gtest.h>

#include "TimeTestHelpers.hpp"
#include "core/time/TimeSelector.hpp"

namespace isph {
namespace {

const std::vector<Instant> all{{0, "0"},     {0.1, "0.1"}, {0.2, "0.2"}, {0.3, "0.3"},
                               {0.5, "0.5"}, {1, "1"},     {1.5, "1.5"}};

std::string names(const std::vector<Instant>& times) {
  std::string out;
  for (const auto& t : times) out += (out.empty() ? "" : " ") + t.name;
  return out;
}

std::string select(std::optional<std::string> ranges, bool latest = false, bool noZero = false) {
  return names(selectTimes(all, TimeSelection{std::move(ranges), latest, noZero}));
}

TEST(TimeSelector, NoOptionSelectsAll) {
  EXPECT_EQ(select(std::nullopt), "0 0.1 0.2 0.3 0.5 1 1.5");
}

TEST(TimeSelector, Ranges) {
  EXPECT_EQ(select("0:0.5"), "0 0.1 0.2 0.3 0.5");
  EXPECT_EQ(select(":0.2"), "0 0.1 0.2");
  EXPECT_EQ(select("1:"), "1 1.5");
  EXPECT_EQ(select("0.15:0.35"), "0.2 0.3");
}

TEST(TimeSelector, SingleValuesPickTheNearestTime) {
  EXPECT_EQ(select("0.1,0.3"), "0.1 0.3");
  EXPECT_EQ(select("0.30000000000000004"), "0.3");
  EXPECT_EQ(select("0.4"), "");  // nothing near: nothing selected (the caller warns)
}

TEST(TimeSelector, SeparatorsAndCombinations) {
  EXPECT_EQ(select("0.1 0.3"), "0.1 0.3");
  EXPECT_EQ(select(" 0.1 ,  :0 , 1.5: "), "0 0.1 1.5");
  EXPECT_EQ(select("0:0.2,1"), "0 0.1 0.2 1");
  EXPECT_EQ(select("0.2", true), "0.2 1.5");
  EXPECT_EQ(select("0:0.2", false, true), "0.1 0.2");
  EXPECT_EQ(select("0:0.2", true, true), "0.1 0.2 1.5");
}

TEST(TimeSelector, LatestTimeAndNoZero) {
  EXPECT_EQ(select(std::nullopt, true), "1.5");
  EXPECT_EQ(select(std::nullopt, false, true), "0.1 0.2 0.3 0.5 1 1.5");
  EXPECT_EQ(names(selectTimes({{0, "0"}}, TimeSelection{std::nullopt, true, true})), "");
  EXPECT_EQ(names(selectTimes({}, TimeSelection{std::nullopt, true, false})), "");
}

TEST(TimeSelector, ParseTimeRanges) {
  const auto r = parseTimeRanges("0:1,2,:3,4:");
  ASSERT_EQ(r.size(), 4u);
  EXPECT_TRUE(r[1].single);
  EXPECT_DOUBLE_EQ(*r[1].lower, 2);
  EXPECT_FALSE(r[2].lower);
  EXPECT_DOUBLE_EQ(*r[2].upper, 3);
  EXPECT_DOUBLE_EQ(*r[3].lower, 4);
  EXPECT_FALSE(r[3].upper);
}

TEST(TimeSelector, BadStrings) {
  for (const char* bad : {"abc", "0.1+0.2:1", "0:1:2", ":", "", " , ", "2:1", "0.1;0.2", "1e:2"}) {
    const auto e = test::expectFatal([&] { parseTimeRanges(bad); });
    const std::string message = e.what();
    EXPECT_NE(message.find("-time"), std::string::npos) << message;
    EXPECT_NE(message.find("expected"), std::string::npos) << message;
    EXPECT_NE(message.find("0:0.5"), std::string::npos) << message;
  }
  const auto e = test::expectFatal([] { selectTimes(all, TimeSelection{"0:x", false, false}); });
  EXPECT_NE(std::string(e.what()).find("'x' is not a number"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace isph
