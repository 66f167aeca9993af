// The PPE's Dirichlet particles (PpeDirichletParticles.hpp) on a 10 × 10 lattice block of
// material, 2D, Wendland C2, h = 1.3 dx: the flagged free surface holds p; a flagged particle
// whose kernel sum exceeds the full lattice's (a clump) stays an unknown when its material is
// kept compressed, not otherwise nor next to a wall; a block with no flag (a full, closed
// container) gets exactly one particle pinned, without which the PPE is singular.
#include "isph/pressure/PpeDirichletParticles.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "LatticeBlockForTest.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01;
constexpr int n = 10;
constexpr std::size_t centre = 5 * n + 5;

struct Block {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps = test::latticeBlock(*kernel, n, dx);
  std::vector<char> flags = std::vector<char>(ps.nMaterial, 0);

  Block() {
    ps.cloud.material.assign(ps.nMaterial, 0);
    // The interior kernel sum, less 1 %: an interior particle counts as compressed.
    double interior = dx * dx * kernel->W(0.0);
    for (long k = ps.neighbours.start[centre]; k < ps.neighbours.start[centre + 1]; ++k) {
      interior += dx * dx * ps.neighbours.W[static_cast<std::size_t>(k)];
    }
    ps.latticeSum = 0.99 * interior;
    for (int i = 0; i < n; ++i) flags[static_cast<std::size_t>((n - 1) * n + i)] = 1;  // the top row
  }
  std::size_t count(const std::vector<char>& f) const { return std::accumulate(f.begin(), f.end(), std::size_t{0}); }
};

TEST(PpeDirichletParticles, TheFlaggedFreeSurfaceHoldsItsPressure) {
  Block b;
  const std::vector<char> d = ppeDirichletParticles(b.ps, *b.kernel, b.flags, {0});
  EXPECT_EQ(d, b.flags) << "the surface as flagged; nothing pinned (every group touches it)";
}

TEST(PpeDirichletParticles, ACompressedFlaggedParticleOfAKeptMaterialStaysAnUnknown) {
  Block b;
  b.flags[centre] = 1;  // flagged, with a full (compressed) support
  EXPECT_EQ(ppeDirichletParticles(b.ps, *b.kernel, b.flags, {1})[centre], 0) << "kept compressed: an unknown";
  EXPECT_EQ(ppeDirichletParticles(b.ps, *b.kernel, b.flags, {0})[centre], 1) << "a fluid: held at p = 0";
}

TEST(PpeDirichletParticles, ACompressedFlaggedParticleNextToAWallIsHeld) {
  Block b;
  // The top row of the block taken as a wall (the last particles: ParticleSystem's order), the
  // particle two rows below it flagged: a wall in its support, so its kernel sum says nothing
  // of a clump, and it is held whatever its material.
  b.ps.nMaterial -= n;
  b.ps.nWall = n;
  std::vector<char> flags(b.ps.nMaterial, 0);
  const std::size_t nearWall = (n - 3) * n + 5;
  flags[nearWall] = 1;
  flags[centre] = 1;  // and one away from the wall, for contrast
  const std::vector<char> d = ppeDirichletParticles(b.ps, *b.kernel, flags, {1});
  EXPECT_EQ(d[nearWall], 1);
  EXPECT_EQ(d[centre], 0);
}

TEST(PpeDirichletParticles, AClosedContainerGetsOneParticlePinned) {
  Block b;
  const std::vector<char> none(b.ps.nMaterial, 0);
  const std::vector<char> d = ppeDirichletParticles(b.ps, *b.kernel, none, {0});
  EXPECT_EQ(b.count(d), 1u);
}

}  // namespace
