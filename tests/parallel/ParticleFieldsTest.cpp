// ParticleFields, the arrays that travel with a particle: packed particles inserted as a block
// before a given particle land there with every field (the cloud's and the caller's) and the
// others keep their order; a block erased leaves the rest in order; keep() reorders every
// field alike. (Local to a rank: it runs alike on every rank of testParallel.)
#include <gtest/gtest.h>

#include "ParallelTestHelpers.hpp"
#include "core/Error.hpp"
#include "parallel/ParticleFields.hpp"

namespace {

using namespace isph;
using isph::test::latticeCloud;

// Every field of particle i of `c` (and of `extra`) is the lattice's particle `id`'s.
void expectParticle(const ParticleCloud& c, const std::vector<double>& extra, std::size_t i,
                    const ParticleCloud& lattice, label id) {
  isph::test::expectSameParticle(c, i, lattice, static_cast<std::size_t>(id));
  EXPECT_EQ(extra[i], 0.5 * static_cast<double>(id)) << "particle " << id;
}

TEST(ParticleFields, InsertPlacesABlockWithEveryFieldAndEraseRemovesIt) {
  const ParticleCloud lattice = latticeCloud(4, 5, 1, 0.01);  // 20 particles
  ParticleCloud mine = lattice, other = lattice;
  std::vector<double> mineExtra(mine.size()), otherExtra(other.size());
  for (std::size_t i = 0; i < lattice.size(); ++i) mineExtra[i] = otherExtra[i] = 0.5 * static_cast<double>(i);
  ParticleFields fields(mine), source(other);
  fields.add(mineExtra);
  source.add(otherExtra);
  fields.keep({0, 1, 2, 3, 4, 5});  // the first six, in order
  ASSERT_EQ(fields.size(), 6u);

  // Particles 12, 17, 9 of the other cloud inserted before the fourth.
  const std::vector<std::byte> packed = source.pack({12, 17, 9});
  fields.insert(3, packed.data(), 3);
  ASSERT_EQ(fields.size(), 9u);
  mine.checkSizes("after insert");
  const std::vector<label> expected{0, 1, 2, 12, 17, 9, 3, 4, 5};
  for (std::size_t i = 0; i < expected.size(); ++i) expectParticle(mine, mineExtra, i, lattice, expected[i]);

  // At the end, as append does, and at the front.
  fields.append(packed.data(), 1);
  fields.insert(0, source.pack({19}).data(), 1);
  const std::vector<label> ends{19, 0, 1, 2, 12, 17, 9, 3, 4, 5, 12};
  ASSERT_EQ(fields.size(), ends.size());
  for (std::size_t i = 0; i < ends.size(); ++i) expectParticle(mine, mineExtra, i, lattice, ends[i]);

  // Erasing the inserted block [4, 7) restores the rest in order.
  fields.erase(4, 3);
  const std::vector<label> left{19, 0, 1, 2, 3, 4, 5, 12};
  ASSERT_EQ(fields.size(), left.size());
  mine.checkSizes("after erase");
  for (std::size_t i = 0; i < left.size(); ++i) expectParticle(mine, mineExtra, i, lattice, left[i]);

  // keep() reorders every field alike.
  fields.keep({7, 0, 4});
  const std::vector<label> kept{12, 19, 3};
  ASSERT_EQ(fields.size(), kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) expectParticle(mine, mineExtra, i, lattice, kept[i]);
}

TEST(ParticleFields, ABlockOutsideTheParticlesIsAnError) {
  ParticleCloud c = latticeCloud(3, 3, 1, 0.01);
  ParticleFields fields(c);
  EXPECT_THROW(fields.erase(8, 2), FatalError);
  EXPECT_THROW(fields.insert(10, nullptr, 0), FatalError);
  EXPECT_THROW(fields.keep({9}), FatalError);
  EXPECT_EQ(fields.size(), 9u) << "a refused call changes nothing";
}

}  // namespace
