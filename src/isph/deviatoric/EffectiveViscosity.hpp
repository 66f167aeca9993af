#pragma once
// The effective viscosity η_a of every material particle from its material model at the
// particle's pressure and shear rate (lagged: time n), and the deviatoric stress τ = 2 η D
// (tension positive; s = −τ in the paper's compression-positive Eq. 3) that is written and
// that the force on a wall integrates.
#include <vector>

#include "core/Types.hpp"
#include "isph/ParticleSystem.hpp"
#include "isph/deviatoric/StrainRate.hpp"

namespace isph {

// η for particles [0, nMaterial); returns the largest η/ρ (for the explicit viscous limit),
// over all ranks of a parallel run.
double effectiveViscosity(const ParticleSystem& ps, const MaterialTable& materials, const StrainRate& strain,
                          std::vector<double>& eta);

// τ = 2 η D for the material particles, zero for the others (size ps.size()).
std::vector<SymmTensor> deviatoricStress(const ParticleSystem& ps, const StrainRate& strain,
                                         const std::vector<double>& eta);

}  // namespace isph
