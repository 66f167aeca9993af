#pragma once
// Which material particles hold their pressure by a Dirichlet row of the PPE
// (PressurePoissonEquation.hpp): the free surface that FreeSurfaceDetector flagged, except
// the compressed particles (kernel sum above the full lattice's) away from walls of the
// materials in `keepCompressed` (granular ones by default): such a particle is no opening to
// the outside but a clump at the surface, and stays an unknown so that its own pressure pushes
// the clump apart (with p = 0 held there, nothing would); and, in every connected group of
// unknowns that touches no Dirichlet particle (a closed, completely filled container), one
// particle pinned to p = 0, without which the system is singular (logged).
#include <vector>

#include "isph/ParticleSystem.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph {

// One flag per material particle (parallel: the ghosts' from their owners).
std::vector<char> ppeDirichletParticles(const ParticleSystem& ps, const Kernel& kernel,
                                        const std::vector<char>& freeSurface, const std::vector<char>& keepCompressed);

}  // namespace isph
