#include "isph/pressure/PpeDirichletParticles.hpp"

#include "core/Log.hpp"
#include "isph/parallel/ClosedRegions.hpp"
#include "isph/parallel/GhostExchange.hpp"

namespace isph {

namespace {

// Marks (in flags) one particle of every connected group of unknowns (dirichlet 0) that
// touches no Dirichlet particle (a closed, completely filled container): without it the
// system is singular. Returns the number of pinned particles.
int pinClosedRegions(const ParticleSystem& ps, const std::vector<char>& touchesDirichlet, std::vector<char>& flags,
                     const std::vector<char>& dirichlet) {
  const std::size_t n = ps.nMaterial;
  std::vector<char> seen(n, 0);
  std::vector<std::size_t> stack;
  int pinned = 0;
  for (std::size_t s = 0; s < n; ++s) {
    if (seen[s] || dirichlet[s]) continue;
    bool anchored = false;
    stack.assign(1, s);
    seen[s] = 1;
    while (!stack.empty()) {
      const std::size_t a = stack.back();
      stack.pop_back();
      anchored = anchored || touchesDirichlet[a];
      for (long k = ps.neighbours.start[a]; k < ps.neighbours.start[a + 1]; ++k) {
        const auto b = static_cast<std::size_t>(ps.neighbours.index[static_cast<std::size_t>(k)]);
        if (b < n && !seen[b] && !dirichlet[b]) {
          seen[b] = 1;
          stack.push_back(b);
        }
      }
    }
    if (!anchored) {
      flags[s] = 1;
      ++pinned;
    }
  }
  return pinned;
}

}  // namespace

std::vector<char> ppeDirichletParticles(const ParticleSystem& ps, const Kernel& kernel,
                                        const std::vector<char>& freeSurface, const std::vector<char>& keepCompressed) {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const std::size_t nMat = ps.nMaterial;
  std::vector<char> flags(freeSurface.begin(), freeSurface.begin() + static_cast<long>(nMat));
  const double W0 = kernel.W(0.0);
  for (std::size_t a = 0; a < nMat; ++a) {
    const auto m = static_cast<std::size_t>(c.material[a]);
    if (!flags[a] || m >= keepCompressed.size() || !keepCompressed[m]) continue;
    double theta = ps.volume[a] * W0;
    bool wall = false;
    for (long k = nl.start[a]; k < nl.start[a + 1] && !wall; ++k) {
      const auto b = static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)]);
      wall = !ps.isMaterial(b);
      theta += ps.volume[b] * nl.W[static_cast<std::size_t>(k)];
    }
    if (!wall && theta > ps.latticeSum) flags[a] = 0;
  }
  exchangeGhosts(ps, flags);  // parallel: a ghost's from its whole neighbourhood

  std::vector<char> touchesDirichlet(nMat, 0);
  for (std::size_t a = 0; a < nMat; ++a) {
    if (flags[a]) continue;
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto b = static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)]);
      if (b < nMat && flags[b]) {
        touchesDirichlet[a] = 1;
        break;
      }
    }
  }
  const std::vector<char> dirichlet(flags);  // before pinning: the groups are of these unknowns
  const int pinned = ps.halo ? pinClosedRegionsAcrossRanks(ps, touchesDirichlet, flags, dirichlet)  // parallel
                             : pinClosedRegions(ps, touchesDirichlet, flags, dirichlet);
  if (pinned > 0) {
    info("    PPE: {} closed region(s) without a free surface: pressure pinned to 0 at one particle each", pinned);
  }
  return flags;
}

}  // namespace isph
