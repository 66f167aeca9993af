#include "isph/deviatoric/EffectiveViscosity.hpp"

#include <algorithm>

#include "isph/parallel/GhostExchange.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

double effectiveViscosity(const ParticleSystem& ps, const MaterialTable& materials, const StrainRate& strain,
                          std::vector<double>& eta) {
  const auto& c = ps.cloud;
  eta.assign(ps.size(), 0.0);
  const long n = static_cast<long>(ps.nMaterial);
  double maxNu = 0;
#pragma omp parallel for schedule(static) reduction(max : maxNu)
  for (long ia = 0; ia < n; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    eta[a] = materials[static_cast<std::size_t>(c.material[a])].viscosity(c.p[a], strain.shearRate[a]);
    if (a < ps.ownMaterial()) maxNu = std::max(maxNu, eta[a] / ps.rho[a]);  // (parallel: the own)
  }
  exchangeGhosts(ps, eta);  // parallel: the pair viscosity reads η at ghosts
  return maxOverRanks(maxNu);
}

std::vector<SymmTensor> deviatoricStress(const ParticleSystem& ps, const StrainRate& strain,
                                         const std::vector<double>& eta) {
  std::vector<SymmTensor> tau(ps.size(), SymmTensor::Zero());
  for (std::size_t a = 0; a < ps.nMaterial; ++a) tau[a] = 2.0 * eta[a] * strain.D[a];
  exchangeGhosts(ps, tau);  // parallel: the walls' stress averages τ over ghosts too
  return tau;
}

}  // namespace isph
