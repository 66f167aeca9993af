#include "isph/parallel/ClosedRegions.hpp"

#include <numeric>

#include "isph/parallel/GhostExchange.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

namespace {

std::size_t findRoot(std::vector<std::size_t>& parent, std::size_t a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

}  // namespace

int pinClosedRegionsAcrossRanks(const ParticleSystem& ps, const std::vector<char>& touchesDirichlet,
                                std::vector<char>& flags, const std::vector<char>& dirichlet) {
  const std::size_t n = ps.nMaterial, own = ps.ownMaterial();
  const auto& nl = ps.neighbours;
  // The own unknowns' groups by their links among themselves.
  std::vector<std::size_t> parent(own);
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t a = 0; a < own; ++a) {
    if (dirichlet[a]) continue;
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto b = static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)]);
      if (b < own && !dirichlet[b]) parent[findRoot(parent, a)] = findRoot(parent, b);
    }
  }
  // Each particle's group label (smallest global row) and whether the group is anchored.
  std::vector<long> label(n, -1);
  std::vector<char> anchored(n, 0);
  std::vector<long> groupLabel(own, -1);
  std::vector<char> groupAnchored(own, 0);
  for (std::size_t a = 0; a < own; ++a) {
    if (dirichlet[a]) continue;
    const std::size_t r = findRoot(parent, a);
    const long row = ps.globalRow(a);
    groupLabel[r] = groupLabel[r] < 0 ? row : std::min(groupLabel[r], row);
    groupAnchored[r] = groupAnchored[r] || touchesDirichlet[a];
  }
  for (bool changed = true; changed;) {
    for (std::size_t a = 0; a < own; ++a) {
      if (dirichlet[a]) continue;
      const std::size_t r = findRoot(parent, a);
      label[a] = groupLabel[r];
      anchored[a] = groupAnchored[r];
    }
    exchangeGhosts(ps, label);
    exchangeGhosts(ps, anchored);
    bool mine = false;
    for (std::size_t a = 0; a < own; ++a) {  // what the groups on other ranks bring
      if (dirichlet[a]) continue;
      const std::size_t r = findRoot(parent, a);
      for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
        const auto b = static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)]);
        if (b < own || b >= n || dirichlet[b] || label[b] < 0) continue;
        if (label[b] < groupLabel[r]) groupLabel[r] = label[b], mine = true;
        if (anchored[b] && !groupAnchored[r]) groupAnchored[r] = 1, mine = true;
      }
    }
    changed = anyRank(mine);
  }
  long pinned = 0;
  for (std::size_t a = 0; a < own; ++a) {
    if (dirichlet[a]) continue;
    const std::size_t r = findRoot(parent, a);
    if (!groupAnchored[r] && groupLabel[r] == ps.globalRow(a)) {
      flags[a] = 1;
      ++pinned;
    }
  }
  exchangeGhosts(ps, flags);
  return static_cast<int>(sumOverRanks(pinned));
}

}  // namespace isph
