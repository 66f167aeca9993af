// What a rank owns of its particle system (OwnedParticles.hpp), in a serial run: no halo, so
// every particle is owned and each function returns the whole, in order; the mean neighbours is
// the neighbour list's own mean. The parallel side (own particles only, over 1, 2 and 3 ranks)
// is checked through the written fields in ParallelCasesTest.cpp (serial and parallel runs give
// the same figures, and reconstructPar the same particles).
#include <gtest/gtest.h>

#include <vector>

#include "LatticeBlockForTest.hpp"
#include "isph/parallel/OwnedParticles.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph {
namespace {

constexpr double dx = 0.01;

ParticleSystem block() {
  const auto kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps = test::latticeBlock(*kernel, 6, dx);
  const std::size_t n = ps.size();
  ps.cloud.origId.resize(n);
  ps.cloud.U.assign(n, Vec3::Zero());
  ps.cloud.p.assign(n, 0.0);
  for (std::size_t a = 0; a < n; ++a) {
    ps.cloud.origId[a] = static_cast<label>(100 + a);
    ps.cloud.p[a] = static_cast<double>(a);
  }
  return ps;
}

TEST(OwnedParticles, ASerialRunOwnsEveryParticle) {
  const ParticleSystem ps = block();
  const std::vector<char> mask = ownedMask(ps);
  ASSERT_EQ(mask.size(), ps.size());
  for (const char owned : mask) EXPECT_EQ(owned, 1);
}

TEST(OwnedParticles, ASerialRunWritesTheWholeFieldAndCloudInOrder) {
  const ParticleSystem ps = block();
  const std::vector<double> field = ownedValues(ps, ps.cloud.p);
  EXPECT_EQ(field, ps.cloud.p);
  const ParticleCloud cloud = ownedCloud(ps);
  ASSERT_EQ(cloud.size(), ps.size());
  EXPECT_EQ(cloud.origId, ps.cloud.origId);
  for (std::size_t a = 0; a < ps.size(); ++a) EXPECT_EQ(cloud.positions[a], ps.cloud.positions[a]);
}

// Counted here by brute force: the other particles within the kernel support (the list leaves
// a particle itself out), averaged over the block's material; a count of integers, so exact.
TEST(OwnedParticles, MeanNeighboursCountsTheOtherParticlesWithinTheSupport) {
  const ParticleSystem ps = block();
  const auto kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  long pairs = 0;
  for (std::size_t a = 0; a < ps.nMaterial; ++a) {
    for (std::size_t b = 0; b < ps.size(); ++b) {
      if (b != a && (ps.cloud.positions[a] - ps.cloud.positions[b]).norm() < kernel->supportRadius()) ++pairs;
    }
  }
  EXPECT_DOUBLE_EQ(meanNeighbours(ps), static_cast<double>(pairs) / static_cast<double>(ps.nMaterial));
}

}  // namespace
}  // namespace isph
