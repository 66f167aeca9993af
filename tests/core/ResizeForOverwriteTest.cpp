#include "core/ResizeForOverwrite.hpp"

#include <gtest/gtest.h>

namespace isph {
namespace {

// A buffer refilled every step whose length creeps up: std::vector::resize would double its
// capacity (1,000 -> 2,000 for one more element); the buffer keeps n plus 1/32.
TEST(ResizeForOverwrite, GrowsToTheLengthPlusAThirtySecond) {
  std::vector<double> v(1000, 1.0);
  v.shrink_to_fit();
  resizeForOverwrite(v, 1001);
  EXPECT_EQ(v.size(), 1001u);
  EXPECT_EQ(v.capacity(), 1001u + 1001u / 32u);  // 1,032: reserve allocates exactly that
}

TEST(ResizeForOverwrite, SmallGrowthWithinTheHeadroomKeepsTheBuffer) {
  std::vector<int> v;
  resizeForOverwrite(v, 3200);
  const int* buffer = v.data();
  resizeForOverwrite(v, 3100);  // shrinks: the buffer stays
  resizeForOverwrite(v, 3300);  // within 3,200 + 100
  EXPECT_EQ(v.size(), 3300u);
  EXPECT_EQ(v.data(), buffer);
  EXPECT_EQ(v.capacity(), 3300u);
}

}  // namespace
}  // namespace isph
