// Neighbour search: the same pairs as a brute-force search, symmetric, with the kernel
// values of each pair; the cell ordering is a permutation.
#include "sph/neighbours/NeighbourList.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

namespace isph {
namespace {

std::vector<Vec3> randomPoints(int n, double size, int dimension, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, size);
  std::vector<Vec3> x(static_cast<std::size_t>(n));
  for (auto& p : x) p = Vec3(u(gen), u(gen), dimension == 3 ? u(gen) : 0.0);
  return x;
}

void expectBruteForcePairs(const std::vector<Vec3>& x, const Kernel& kernel) {
  NeighbourList list;
  list.build(x, kernel);
  ASSERT_EQ(list.nParticles(), x.size());
  const double R = kernel.supportRadius();
  std::size_t pairs = 0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    std::set<int> expected;
    for (std::size_t b = 0; b < x.size(); ++b) {
      if (a != b && (x[a] - x[b]).norm() < R) expected.insert(static_cast<int>(b));
    }
    std::set<int> found;
    for (long k = list.start[a]; k < list.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      found.insert(list.index[kk]);
      const double r = (x[a] - x[static_cast<std::size_t>(list.index[kk])]).norm();
      EXPECT_DOUBLE_EQ(list.W[kk], kernel.W(r));
      EXPECT_NEAR(list.F[kk] * r, kernel.dWdr(r), 1e-9 * std::abs(kernel.dWdr(r)) + 1e-300);
    }
    EXPECT_EQ(found, expected) << "particle " << a;
    pairs += expected.size();
  }
  EXPECT_EQ(list.nPairs(), pairs);
}

TEST(NeighbourList, MatchesBruteForceIn2D) {
  const auto kernel = makeKernel("WendlandC2", 0.013, 2);
  expectBruteForcePairs(randomPoints(1500, 0.3, 2, 1), *kernel);
}

TEST(NeighbourList, MatchesBruteForceIn3D) {
  const auto kernel = makeKernel("WendlandC2", 0.03, 3);
  expectBruteForcePairs(randomPoints(1000, 0.3, 3, 2), *kernel);
}

// Given the material count, a material particle's row is whole and another's (a wall's or a
// dummy's) holds its material neighbours only, in the order they have in the whole row, with
// the same kernel values: every sum a wall particle takes over its material is unchanged to the
// last bit.
TEST(NeighbourList, RowsPastTheMaterialHoldTheirMaterialNeighboursInTheWholeRowsOrder) {
  const auto kernel = makeKernel("WendlandC2", 0.013, 2);
  const std::vector<Vec3> x = randomPoints(1500, 0.3, 2, 3);
  const std::size_t nMaterial = 900;
  NeighbourList whole, cut;
  whole.build(x, *kernel);
  cut.build(x, *kernel, nMaterial);
  ASSERT_EQ(cut.nParticles(), x.size());
  std::size_t wallRowsWithMaterial = 0, pairsLeftOut = 0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    std::vector<int> expected;
    std::vector<double> W, F;
    for (long k = whole.start[a]; k < whole.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      if (a < nMaterial || static_cast<std::size_t>(whole.index[kk]) < nMaterial) {
        expected.push_back(whole.index[kk]);
        W.push_back(whole.W[kk]);
        F.push_back(whole.F[kk]);
      } else {
        ++pairsLeftOut;
      }
    }
    const auto first = static_cast<std::size_t>(cut.start[a]), last = static_cast<std::size_t>(cut.start[a + 1]);
    EXPECT_EQ(std::vector<int>(cut.index.begin() + first, cut.index.begin() + last), expected) << "particle " << a;
    EXPECT_EQ(std::vector<double>(cut.W.begin() + first, cut.W.begin() + last), W) << "particle " << a;
    EXPECT_EQ(std::vector<double>(cut.F.begin() + first, cut.F.begin() + last), F) << "particle " << a;
    wallRowsWithMaterial += a >= nMaterial && last > first;
  }
  EXPECT_GT(wallRowsWithMaterial, 100u);  // (the case is not empty: rows past the material with material in them)
  EXPECT_GT(pairsLeftOut, 1000u);         // ... and pairs among the others, left out
  EXPECT_EQ(cut.nPairs() + pairsLeftOut, whole.nPairs());
}

// A particle marked without a row (a parallel run's ghost) has an empty row and stays in the
// others' rows, which are as they would be with every row built.
TEST(NeighbourList, AParticleWithoutARowStaysANeighbourOfTheOthers) {
  const auto kernel = makeKernel("WendlandC2", 0.013, 2);
  const std::vector<Vec3> x = randomPoints(1500, 0.3, 2, 4);
  std::vector<char> withRow(x.size(), 1);
  for (std::size_t a = 0; a < x.size(); a += 3) withRow[a] = 0;
  NeighbourList whole, some;
  whole.build(x, *kernel, 900);
  some.build(x, *kernel, 900, &withRow);
  std::size_t seenInOthers = 0;
  for (std::size_t a = 0; a < x.size(); ++a) {
    const auto first = static_cast<std::size_t>(some.start[a]), last = static_cast<std::size_t>(some.start[a + 1]);
    if (!withRow[a]) {
      EXPECT_EQ(first, last) << "particle " << a;
      continue;
    }
    const auto wFirst = static_cast<std::size_t>(whole.start[a]), wLast = static_cast<std::size_t>(whole.start[a + 1]);
    EXPECT_EQ(std::vector<int>(some.index.begin() + first, some.index.begin() + last),
              std::vector<int>(whole.index.begin() + wFirst, whole.index.begin() + wLast)) << "particle " << a;
    EXPECT_EQ(std::vector<double>(some.F.begin() + first, some.F.begin() + last),
              std::vector<double>(whole.F.begin() + wFirst, whole.F.begin() + wLast)) << "particle " << a;
    for (std::size_t k = first; k < last; ++k) seenInOthers += !withRow[static_cast<std::size_t>(some.index[k])];
  }
  EXPECT_GT(seenInOthers, 1000u);  // the rowless particles are still found as neighbours
}

TEST(NeighbourList, SquareLatticeHas20NeighboursInTheInterior) {
  const double dx = 0.01;
  std::vector<Vec3> x;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) x.emplace_back(i * dx, j * dx, 0);
  NeighbourList list;
  list.build(x, *makeKernel("WendlandC2", 1.3 * dx, 2));
  const std::size_t centre = 10 * 20 + 10;
  EXPECT_EQ(list.start[centre + 1] - list.start[centre], 20);  // 21 with the particle itself
}

TEST(NeighbourList, CellOrderIsAPermutationThatGroupsNeighbours) {
  const auto x = randomPoints(2000, 1.0, 2, 3);
  auto order = cellOrder(x, 0.05, 2);
  ASSERT_EQ(order.size(), x.size());
  auto sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], static_cast<int>(i));
  // Consecutive particles in the new order are on average much closer than in random order.
  double before = 0, after = 0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    before += (x[i] - x[i - 1]).norm();
    after += (x[static_cast<std::size_t>(order[i])] - x[static_cast<std::size_t>(order[i - 1])]).norm();
  }
  EXPECT_LT(after, 0.25 * before);
}

TEST(NeighbourList, ParticleFarOutsideIsAClearError) {
  auto x = randomPoints(10, 0.1, 2, 4);
  x[3] = Vec3(1e9, 0, 0);
  NeighbourList list;
  EXPECT_THROW(list.build(x, *makeKernel("WendlandC2", 0.01, 2)), FatalError);
}

}  // namespace
}  // namespace isph
