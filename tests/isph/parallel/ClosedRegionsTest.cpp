// The PPE's closed regions across ranks (ClosedRegions.hpp): a lattice cut into a left and a
// right group of unknowns by a band of Dirichlet particles wider than the kernel support; the right group touches a
// Dirichlet particle, the left group does not and spans two ranks. Exactly one particle is
// pinned over all ranks, the left group's of smallest global row, on its owner and as a ghost.
// Part of testParallel (tests/parallel/CMakeLists.txt: 1 and 3 ranks).
#include <gtest/gtest.h>

#include <numeric>

#include "../../parallel/ParallelTestHelpers.hpp"
#include "isph/parallel/ClosedRegions.hpp"
#include "parallel/GlobalNumbering.hpp"
#include "parallel/Migration.hpp"
#include "parallel/Reduce.hpp"
#include "parallel/ZoltanPartitioner.hpp"

namespace {

using namespace isph;

TEST(ClosedRegions, TheGroupWithoutADirichletParticleIsPinnedOnceAcrossTheRanks) {
  const int nx = 60, ny = 8;
  const double dx = 0.01;
  // Material only: all rows of the helper's lattice from its third up (its bottom two are walls).
  ParticleCloud all = test::latticeCloud(nx, ny + 2, 1, dx);
  ParticleCloud mine = test::everyNth(all, thisRank(), nRanks());
  {
    std::vector<std::size_t> material;
    for (std::size_t i = 0; i < mine.size(); ++i) {
      if (mine.kind[i] == 0) material.push_back(i);
    }
    ParticleFields(mine).keep(material);
  }
  ParticleFields fields(mine);
  ZoltanPartitioner zoltan("RCB", 2, nRanks());
  migrateParticles(fields, zoltan.partition(mine.positions, std::vector<double>(mine.size(), 1.0), mine.origId));

  // Own, then ghosts (with their owners' global rows).
  const auto kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  ParticleSystem ps;
  ps.dimension = 2;
  ps.dx = dx;
  const std::size_t own = mine.size();
  const GlobalNumbering rows = GlobalNumbering::of(static_cast<long>(own));
  std::vector<long> row(own);
  std::iota(row.begin(), row.end(), rows.first);
  Halo halo(mine.positions, kernel->supportRadius(), 2);
  ps.cloud = mine;
  ParticleFields ownFields(mine), local(ps.cloud);
  ownFields.add(row);
  std::vector<long> localRow = row;
  local.add(localRow);
  halo.sendParticles(ownFields, local);
  std::vector<std::size_t> sent(halo.sent()), ghosts(halo.nGhosts());
  std::iota(ghosts.begin(), ghosts.end(), own);
  halo.setLayout(sent, ghosts, ps.cloud.size(), ps.cloud.size());
  ps.nMaterial = ps.cloud.size();
  ps.nOwnedMaterial = own;
  ps.firstRow = rows.first;
  ps.ghostRow.assign(localRow.begin() + static_cast<long>(own), localRow.end());
  ps.halo = &halo;
  ps.neighbours.build(ps.cloud.positions, *kernel);

  // Columns 39-41 (lattice index: origId % nx) Dirichlet, three spacings wide (the support
  // is 2.6): the groups left and right of it are apart; the right one touches it.
  const std::size_t n = ps.nMaterial;
  std::vector<char> flags(n, 0), touches(n, 0);
  auto column = [&](std::size_t a) { return static_cast<int>(ps.cloud.origId[a] % nx); };
  for (std::size_t a = 0; a < n; ++a) {
    flags[a] = column(a) >= 39 && column(a) <= 41;
    touches[a] = column(a) == 42;
  }
  const std::vector<char> dirichlet(flags);
  const int pinned = pinClosedRegionsAcrossRanks(ps, touches, flags, dirichlet);
  EXPECT_EQ(pinned, 1);

  // The expected pin: the left group's smallest global row, over all ranks.
  long smallest = rows.nGlobal;
  for (std::size_t a = 0; a < own; ++a) {
    if (column(a) < 39) smallest = std::min(smallest, ps.globalRow(a));
  }
  smallest = -maxOverRanks(-smallest);
  long pins = 0;
  for (std::size_t a = 0; a < n; ++a) {
    const bool expected = dirichlet[a] || ps.globalRow(a) == smallest;
    EXPECT_EQ(static_cast<bool>(flags[a]), expected) << "particle " << ps.cloud.origId[a] << ", row " << ps.globalRow(a);
    pins += a < own && flags[a] && !dirichlet[a];
  }
  EXPECT_EQ(sumOverRanks(pins), 1);
  if (nRanks() > 1) {  // the left group (39 columns) spans ranks: RCB cuts the 60 into parts of 20 or 30
    long leftRanks = 0;
    for (std::size_t a = 0; a < own; ++a) {
      if (column(a) < 39) {
        leftRanks = 1;
        break;
      }
    }
    EXPECT_GT(sumOverRanks(leftRanks), 1);
  }
}

}  // namespace
