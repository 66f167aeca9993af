#include "isph/LaggedPressure.hpp"

#include <algorithm>

#include "isph/parallel/GhostExchange.hpp"

namespace isph {

std::vector<double> smoothedPressure(const ParticleSystem& ps, const Kernel& kernel,
                                     const std::vector<char>& freeSurface, int passes) {
  const std::size_t n = ps.nMaterial;
  std::vector<double> p(ps.cloud.p.begin(), ps.cloud.p.begin() + static_cast<long>(n));
  std::vector<double> next(n);
  const double W0 = kernel.W(0.0);
  const auto& nl = ps.neighbours;
  for (int pass = 0; pass < passes; ++pass) {
#pragma omp parallel for schedule(static)
    for (long ia = 0; ia < static_cast<long>(n); ++ia) {
      const auto a = static_cast<std::size_t>(ia);
      if (freeSurface[a]) {
        next[a] = 0.0;
        continue;
      }
      double sum = ps.volume[a] * W0 * p[a], weight = ps.volume[a] * W0;
      for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        const auto b = static_cast<std::size_t>(nl.index[kk]);
        if (!ps.isMaterial(b)) continue;
        sum += ps.volume[b] * nl.W[kk] * p[b];
        weight += ps.volume[b] * nl.W[kk];
      }
      next[a] = sum / weight;
    }
    std::swap(p, next);
    exchangeGhosts(ps, p);  // parallel: the next pass reads the ghosts'
  }
  return p;
}

}  // namespace isph
