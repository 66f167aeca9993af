// Zoltan's RCB and HSFC through ZoltanPartitioner: every point gets one part, the parts carry
// equal weight within Zoltan's tolerance, the kept cuts place every point in its own part,
// and nothing assumes 2D. Runs on any number of ranks (ctest: 1 and 3), each starting with
// every n-th point of the lattice, as after a read on one rank.
#include <gtest/gtest.h>

#include "ParallelTestHelpers.hpp"
#include "parallel/Reduce.hpp"
#include "parallel/ZoltanPartitioner.hpp"

namespace {

using namespace isph;
using isph::test::everyNth;
using isph::test::latticeCloud;

struct PartitionCase {
  std::string algorithm;
  int dimension;
  int nParts;  // 0: the number of ranks
};

class Partition : public ::testing::TestWithParam<PartitionCase> {};

TEST_P(Partition, GivesEveryPointOnePartOfEqualWeightAndKeepsItsCuts) {
  const auto& [algorithm, dimension, partsWanted] = GetParam();
  const int nParts = partsWanted > 0 ? partsWanted : nRanks();
  const ParticleCloud all = dimension == 3 ? latticeCloud(14, 12, 10, 0.01) : latticeCloud(60, 40, 1, 0.01);
  const ParticleCloud mine = everyNth(all, thisRank(), nRanks());
  // Material particles weigh more than the walls' (as the solver weights them).
  std::vector<double> weights(mine.size());
  for (std::size_t i = 0; i < mine.size(); ++i) weights[i] = mine.kind[i] == 0 ? 1.0 : 0.25;

  ZoltanPartitioner zoltan(algorithm, dimension, nParts);
  const std::vector<int> part = zoltan.partition(mine.positions, weights, mine.origId);
  ASSERT_EQ(part.size(), mine.size());
  std::vector<double> load(static_cast<std::size_t>(nParts), 0.0);
  for (std::size_t i = 0; i < mine.size(); ++i) {
    ASSERT_GE(part[i], 0);
    ASSERT_LT(part[i], nParts);
    load[static_cast<std::size_t>(part[i])] += weights[i];
    // The cuts kept for partOf place the point where the partition put it.
    EXPECT_EQ(zoltan.partOf(mine.positions[i]), part[i]) << "point " << mine.origId[i];
  }
  sumOverRanks(std::span<double>(load));
  double total = 0;
  for (const double l : load) total += l;
  double expected = 0;
  for (std::size_t i = 0; i < all.size(); ++i) expected += all.kind[i] == 0 ? 1.0 : 0.25;
  EXPECT_NEAR(total, expected, 1e-9) << "every point is counted once";
  // Zoltan's IMBALANCE_TOL is 1.02; a part holds whole points (weights 1 and 0.25), so allow
  // one point more of ~2400/nParts.
  EXPECT_LT(imbalance(load), 1.03) << algorithm << " into " << nParts << " parts";
}

INSTANTIATE_TEST_SUITE_P(
    RcbAndHsfc, Partition,
    ::testing::Values(PartitionCase{"RCB", 2, 0}, PartitionCase{"HSFC", 2, 0}, PartitionCase{"RCB", 3, 0},
                      PartitionCase{"HSFC", 3, 0},
                      // decomposePar: more parts than ranks (a whole case read on one rank)
                      PartitionCase{"RCB", 2, 4}, PartitionCase{"HSFC", 2, 5}),
    [](const auto& info) {
      return info.param.algorithm + std::to_string(info.param.dimension) + "D" +
             (info.param.nParts ? std::to_string(info.param.nParts) + "parts" : std::string("ranks"));
    });

// RCB cuts space into boxes: the parts' bounding boxes do not overlap (beyond the cut line).
TEST(Partition, RcbPartsAreBoxesThatDoNotOverlap) {
  const ParticleCloud all = latticeCloud(60, 40, 1, 0.01);
  const ParticleCloud mine = everyNth(all, thisRank(), nRanks());
  const int nParts = 4;
  ZoltanPartitioner zoltan("RCB", 2, nParts);
  const std::vector<int> part = zoltan.partition(mine.positions, std::vector<double>(mine.size(), 1.0), mine.origId);
  // Each point of the whole lattice, assigned by the cuts: count the points of another part
  // inside each part's bounding box.
  std::vector<Vec3> lo(nParts, Vec3::Constant(1e300)), hi(nParts, Vec3::Constant(-1e300));
  std::vector<int> where(all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    where[i] = zoltan.partOf(all.positions[i]);
    lo[where[i]] = lo[where[i]].cwiseMin(all.positions[i]);
    hi[where[i]] = hi[where[i]].cwiseMax(all.positions[i]);
  }
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (int q = 0; q < nParts; ++q) {
      if (q == where[i]) continue;
      const Vec3& x = all.positions[i];
      const bool inside = x.x() > lo[q].x() && x.x() < hi[q].x() && x.y() > lo[q].y() && x.y() < hi[q].y();
      EXPECT_FALSE(inside) << "point " << i << " of part " << where[i] << " inside part " << q << "'s box";
    }
  }
}

}  // namespace

namespace {

using namespace isph;

// A dummy particle is partitioned at its wall particle's place: two objects at one point,
// which RCB's balancing may split between parts. partition() places both by the kept cuts.
TEST(Partition, EqualPointsShareTheirPart) {
  const ParticleCloud all = test::latticeCloud(40, 30, 1, 0.01);
  ParticleCloud mine = test::everyNth(all, thisRank(), nRanks());
  std::vector<Vec3> points;
  std::vector<label> ids;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    for (int copy = 0; copy < 2; ++copy) {
      points.push_back(Vec3(std::round(mine.positions[i].x() / 0.01) * 0.01, 0.0, 0.0));  // whole columns equal
      ids.push_back(2 * mine.origId[i] + copy);
    }
  }
  for (const char* algorithm : {"RCB", "HSFC"}) {
    ZoltanPartitioner zoltan(algorithm, 2, 3);
    const std::vector<int> part = zoltan.partition(points, std::vector<double>(points.size(), 1.0), ids);
    // Every point of a column (x) in one part, on every rank.
    std::vector<long> first(40, -1), clash(1, 0);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const auto column = static_cast<std::size_t>(std::lround(points[k].x() / 0.01));
      if (first[column] < 0) first[column] = part[k];
      clash[0] += first[column] != part[k];
    }
    std::vector<long> lowest(40), highest(40);
    for (std::size_t c = 0; c < 40; ++c) {
      lowest[c] = first[c] < 0 ? -1000 : -first[c];  // (a column this rank lacks counts for neither)
      highest[c] = first[c];
    }
    sumOverRanks(std::span<long>(clash));
    EXPECT_EQ(clash[0], 0) << algorithm << ": equal points in different parts";
    for (std::size_t c = 0; c < 40; ++c) {
      EXPECT_EQ(-maxOverRanks(lowest[c]), maxOverRanks(highest[c])) << algorithm << ": column " << c << " split over ranks";
    }
  }
}

}  // namespace
