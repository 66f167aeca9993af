// Contiguous global row blocks: rank r's rows follow rank r-1's, from 0.
#include <gtest/gtest.h>

#include "parallel/GlobalNumbering.hpp"
#include "parallel/Reduce.hpp"

namespace {

using namespace isph;

TEST(GlobalNumbering, EachRanksRowsFollowThoseOfTheRanksBefore) {
  const long r = thisRank(), n = nRanks();
  const GlobalNumbering rows = GlobalNumbering::of(r + 1);  // rank r holds r + 1 rows
  EXPECT_EQ(rows.first, r * (r + 1) / 2);
  EXPECT_EQ(rows.nLocal, r + 1);
  EXPECT_EQ(rows.nGlobal, n * (n + 1) / 2);
  EXPECT_EQ(rows.row(0), rows.first);
  EXPECT_TRUE(rows.owns(rows.first + r));
  EXPECT_FALSE(rows.owns(rows.first + r + 1));
  // Every row of 0 .. nGlobal - 1 belongs to exactly one rank.
  std::vector<long> owners(static_cast<std::size_t>(rows.nGlobal), 0);
  for (long i = 0; i < rows.nLocal; ++i) ++owners[static_cast<std::size_t>(rows.row(i))];
  sumOverRanks(std::span<long>(owners));
  for (const long o : owners) EXPECT_EQ(o, 1);
}

TEST(GlobalNumbering, ARankWithoutRowsIsAllowed) {
  const GlobalNumbering rows = GlobalNumbering::of(thisRank() == 0 ? 0 : 5);
  EXPECT_EQ(rows.first, thisRank() == 0 ? 0 : 5L * (thisRank() - 1));
  EXPECT_EQ(rows.nGlobal, 5L * (nRanks() - 1));
}

}  // namespace
