// The ghost halo: a pair loop over a rank's own particles with its ghosts gives what the
// serial loop over all particles gives; exchange() carries each owner's value of a field to
// its ghosts (all particles, or the material ones alone); a dummy's wall comes with it.
#include <gtest/gtest.h>

#include <map>

#include "ParallelTestHelpers.hpp"
#include "parallel/Halo.hpp"
#include "parallel/Migration.hpp"
#include "parallel/ParticleFields.hpp"
#include "parallel/Reduce.hpp"
#include "parallel/ZoltanPartitioner.hpp"
#include "sph/kernels/Kernel.hpp"
#include "sph/neighbours/NeighbourList.hpp"

namespace {

using namespace isph;
using isph::test::everyNth;
using isph::test::latticeCloud;

// A pair loop of the kind the solver runs: the Shepard mean of f and the kernel gradient of f.
struct PairSums {
  double shepard;
  Vec3 gradient;
};
PairSums pairSums(const std::vector<Vec3>& x, const std::vector<double>& f, const NeighbourList& nl, std::size_t a,
                  double W0) {
  double sum = W0 * f[a], weight = W0;
  Vec3 grad = Vec3::Zero();
  for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
    const auto b = static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)]);
    sum += nl.W[static_cast<std::size_t>(k)] * f[b];
    weight += nl.W[static_cast<std::size_t>(k)];
    grad += (f[b] - f[a]) * nl.F[static_cast<std::size_t>(k)] * (x[a] - x[b]);
  }
  return {sum / weight, grad};
}

// The same scene on every rank: partitioned (RCB), owned particles sorted material first.
struct DistributedScene {
  ParticleCloud all, mine;
  int dimension;
};

DistributedScene distribute(int nx, int ny, int nz, double dx) {
  DistributedScene s{latticeCloud(nx, ny, nz, dx), {}, nz > 1 ? 3 : 2};
  s.mine = everyNth(s.all, thisRank(), nRanks());
  ParticleFields fields(s.mine);
  ZoltanPartitioner zoltan("RCB", s.dimension, nRanks());
  migrateParticles(fields, zoltan.partition(s.mine.positions, std::vector<double>(s.mine.size(), 1.0), s.mine.origId));
  return s;
}

class HaloPairLoop : public ::testing::TestWithParam<int> {};

TEST_P(HaloPairLoop, EqualsTheSerialLoopForEveryOwnParticle) {
  const int dimension = GetParam();
  const double dx = 0.01;
  DistributedScene s = dimension == 3 ? distribute(12, 10, 9, dx) : distribute(40, 30, 1, dx);
  const auto kernel = makeKernel("WendlandC2", 1.3 * dx, dimension);

  // Serial reference over the whole lattice.
  std::vector<double> fAll(s.all.size());
  for (std::size_t i = 0; i < s.all.size(); ++i) fAll[i] = std::sin(40 * s.all.positions[i].x()) + s.all.positions[i].y();
  NeighbourList serial;
  serial.build(s.all.positions, *kernel);

  // Owned + ghosts.
  const std::size_t nOwned = s.mine.size();
  const Halo halo(s.mine.positions, kernel->supportRadius(), dimension);
  ParticleCloud local = s.mine;
  ParticleFields owned(s.mine), withGhosts(local);
  halo.sendParticles(owned, withGhosts);
  ASSERT_EQ(local.size(), nOwned + halo.nGhosts());
  EXPECT_EQ(sumOverRanks(nOwned), s.all.size());
  std::vector<double> f(local.size());
  for (std::size_t i = 0; i < local.size(); ++i) f[i] = std::sin(40 * local.positions[i].x()) + local.positions[i].y();
  NeighbourList nl;
  nl.build(local.positions, *kernel);

  const double W0 = kernel->W(0);
  for (std::size_t a = 0; a < nOwned; ++a) {
    const auto id = static_cast<std::size_t>(local.origId[a]);
    ASSERT_EQ(nl.start[a + 1] - nl.start[a], serial.start[id + 1] - serial.start[id]) << "neighbours of " << id;
    const PairSums got = pairSums(local.positions, f, nl, a, W0), want = pairSums(s.all.positions, fAll, serial, id, W0);
    EXPECT_NEAR(got.shepard, want.shepard, 1e-12 * (1 + std::abs(want.shepard))) << "particle " << id;
    EXPECT_LT((got.gradient - want.gradient).norm(), 1e-10 * (1 + want.gradient.norm())) << "particle " << id;
  }
  if (nRanks() > 1) {
    EXPECT_GT(sumOverRanks(static_cast<long>(halo.nGhosts())), 0);
  }
}

INSTANTIATE_TEST_SUITE_P(TwoAndThreeDimensions, HaloPairLoop, ::testing::Values(2, 3));

TEST(Halo, ExchangeCarriesEachOwnersValueToItsGhosts) {
  const double dx = 0.01;
  DistributedScene s = distribute(40, 30, 1, dx);
  // Material first, then the walls and dummies, as the solver orders its particles.
  std::vector<std::size_t> order;
  for (int kind = 0; kind < 3; ++kind) {
    for (std::size_t i = 0; i < s.mine.size(); ++i) {
      if (s.mine.kind[i] == kind) order.push_back(i);
    }
  }
  ParticleFields(s.mine).keep(order);
  const std::size_t nOwned = s.mine.size();
  Halo halo(s.mine.positions, 2.6 * dx, 2);
  ParticleCloud ghosts;
  ParticleFields owned(s.mine), ghostFields(ghosts);
  halo.sendParticles(owned, ghostFields);
  // Local layout: owned material, ghost material, owned others, ghost others.
  std::vector<std::size_t> ownedPlace(nOwned), ghostPlace(ghosts.size());
  std::size_t next = 0;
  for (const bool material : {true, false}) {
    for (std::size_t i = 0; i < nOwned; ++i) {
      if ((s.mine.kind[i] == 0) == material) ownedPlace[i] = next++;
    }
    for (std::size_t g = 0; g < ghosts.size(); ++g) {
      if ((ghosts.kind[g] == 0) == material) ghostPlace[g] = next++;
    }
  }
  std::size_t nMaterial = 0;
  for (std::size_t i = 0; i < nOwned; ++i) nMaterial += s.mine.kind[i] == 0;
  for (std::size_t g = 0; g < ghosts.size(); ++g) nMaterial += ghosts.kind[g] == 0;
  std::vector<std::size_t> sendLocal;
  for (const std::size_t i : halo.sent()) sendLocal.push_back(ownedPlace[i]);
  halo.setLayout(sendLocal, ghostPlace, next, nMaterial);
  const Halo& h = halo;

  std::vector<label> id(next, -1);
  for (std::size_t i = 0; i < nOwned; ++i) id[ownedPlace[i]] = s.mine.origId[i];
  for (std::size_t g = 0; g < ghosts.size(); ++g) id[ghostPlace[g]] = ghosts.origId[g];
  std::vector<Vec3> all(next, Vec3::Constant(-1));
  std::vector<double> material(nMaterial, -1);
  for (std::size_t i = 0; i < nOwned; ++i) {
    const std::size_t l = ownedPlace[i];
    all[l] = Vec3(id[l], 2.0 * id[l], 0);
    if (l < nMaterial) material[l] = 0.25 * id[l];
  }
  h.exchange(all);
  h.exchange(material);
  for (std::size_t l = 0; l < next; ++l) {
    EXPECT_EQ(all[l], Vec3(id[l], 2.0 * id[l], 0)) << "local " << l;
    if (l < nMaterial) {
      EXPECT_EQ(material[l], 0.25 * id[l]) << "local " << l;
    }
  }
  std::vector<double> wrongLength(nMaterial + 1);
  EXPECT_THROW(h.exchange(wrongLength), FatalError);
}

// Rank r holds, along a line, a wall particle at x = 10r + 1, a material particle at 10r + 5
// and a dummy at 10r + 9 whose wall is that wall particle: the next rank's box (x from 10r + 11,
// grown by the radius 3) takes the dummy but not the wall, which must come with it.
TEST(Halo, ADummyBringsItsWall) {
  const int r = thisRank();
  ParticleCloud mine;
  const auto base = static_cast<label>(3 * r);
  mine.push_back(Vec3(10 * r + 1, 1, 0), base, Vec3::Zero(), 0, -1, ParticleKind::wall, 0, Vec3::UnitY(), 1);
  mine.push_back(Vec3(10 * r + 5, 0, 0), base + 1, Vec3::Zero(), 0, 0, ParticleKind::material, -1, Vec3::Zero(), 1);
  mine.push_back(Vec3(10 * r + 9, 0, 0), base + 2, Vec3::Zero(), 0, -1, ParticleKind::dummy, 0, Vec3::Zero(), 1);
  const std::vector<int> companion{-1, -1, 0};
  const Halo halo(mine.positions, 3.0, 2, companion);
  ParticleCloud ghosts;
  ParticleFields owned(mine), ghostFields(ghosts);
  halo.sendParticles(owned, ghostFields);
  std::map<label, int> count;
  for (const label id : ghosts.origId) ++count[id];
  if (r > 0) {
    const auto before = static_cast<label>(3 * (r - 1));
    EXPECT_EQ(count[before + 2], 1) << "the dummy of rank " << r - 1;
    EXPECT_EQ(count[before], 1) << "its wall, with it";
    EXPECT_EQ(count.count(before + 1), 0u) << "the material particle between them is out of reach";
  }
  for (const auto& [id, n] : count) EXPECT_EQ(n, 1) << "ghost " << id << " arrived once";
  if (nRanks() == 1) {
    EXPECT_EQ(ghosts.size(), 0u);
  }
}

}  // namespace
