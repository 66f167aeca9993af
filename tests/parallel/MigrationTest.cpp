// Migration (Zoltan's communication package): after the particles moved, each goes to the
// rank whose part now holds it, arrives there once, with every field (the cloud's and the
// caller's own), and the ones that stayed keep their order.
#include <gtest/gtest.h>

#include "ParallelTestHelpers.hpp"
#include "parallel/Migration.hpp"
#include "parallel/ParticleFields.hpp"
#include "parallel/Reduce.hpp"
#include "parallel/ZoltanPartitioner.hpp"

namespace {

using namespace isph;
using isph::test::everyNth;
using isph::test::latticeCloud;

TEST(Migration, AParticleThatCrossesAPartBoundaryArrivesOnceWithEveryField) {
  const double dx = 0.01;
  const ParticleCloud all = latticeCloud(50, 30, 1, dx);
  ParticleCloud mine = everyNth(all, thisRank(), nRanks());
  std::vector<double> extra(mine.size());
  std::vector<label> tag(mine.size());
  for (std::size_t i = 0; i < mine.size(); ++i) {
    extra[i] = 0.5 * mine.origId[i];
    tag[i] = 7 * mine.origId[i];
  }
  ParticleFields fields(mine);
  fields.add(extra);
  fields.add(tag);

  // Partition, move everything to its part, then shift the particles by three spacings along
  // x (those near a cut cross it) and move them again, by the kept cuts.
  ZoltanPartitioner zoltan("RCB", 2, nRanks());
  std::vector<int> part = zoltan.partition(mine.positions, std::vector<double>(mine.size(), 1.0), mine.origId);
  migrateParticles(fields, part);
  for (Vec3& x : mine.positions) x.x() += 3 * dx;
  std::vector<int> destination(mine.size());
  std::vector<label> staying;
  for (std::size_t i = 0; i < mine.size(); ++i) {
    destination[i] = zoltan.partOf(mine.positions[i]);
    if (destination[i] == thisRank()) staying.push_back(mine.origId[i]);
  }
  const long crossing = sumOverRanks(static_cast<long>(mine.size() - staying.size()));
  const std::size_t arrived = migrateParticles(fields, destination);
  if (nRanks() > 1) {
    EXPECT_GT(crossing, 0) << "the shift must move some particles across a cut";
  }

  ASSERT_EQ(mine.size(), staying.size() + arrived);
  mine.checkSizes("after migration");
  std::vector<long> seen(all.size(), 0);
  for (std::size_t i = 0; i < mine.size(); ++i) {
    const label id = mine.origId[i];
    if (i < staying.size()) {
      EXPECT_EQ(id, staying[i]) << "the particles that stayed keep their order";
    }
    EXPECT_EQ(zoltan.partOf(mine.positions[i]), thisRank()) << "particle " << id << " is on the rank of its part";
    const auto a = static_cast<std::size_t>(id);
    isph::test::expectSameParticle(mine, i, all, a, Vec3(3 * dx, 0, 0));
    EXPECT_EQ(extra[i], 0.5 * id);
    EXPECT_EQ(tag[i], 7 * id);
    ++seen[a];
  }
  sumOverRanks(std::span<long>(seen));
  for (std::size_t a = 0; a < all.size(); ++a) ASSERT_EQ(seen[a], 1) << "particle " << a << " once over all ranks";
}

}  // namespace
