#pragma once
// The pressure that the viscous solve of the incremental projection sees (stages/IncrementalProjection.hpp),
// in the form chosen by isphSchemes `laggedPressure { form pairs | gradient; smoothing N; }`:
//
// - pairs (the default): the symmetric pair force −Σ_b m_b (p_a/ρ_a² + p_b/ρ_b²)∇_a W_ab of
//   pⁿ (laggedPressureForce in VelocityCorrection.hpp), whose wall pairs give the normal
//   reaction that the Coulomb friction is limited by. Where the support is cut (the free
//   surface, a front) it carries an error of order pⁿ_a/(ρ h) that the increment, corrected
//   with the difference form of Eq. 11, does not remove: a granular column collapsing with it
//   ran off the end of its floor (doc/notes/columnCollapse.md).
// - gradient: −∇p̃_a/ρ_a with the renormalised difference gradient of Eq. 11 itself
//   (pressureGradient, walls with the condition of WallBoundaryPressure), so that a pressure
//   that needs no increment moves nothing: the splitting error of the plain projection,
//   dt ∇∇p/ρ per step, is gone where δp → 0. The friction is then limited by the wall
//   pressures, as in the plain projection. p̃ is pⁿ smoothed by `smoothing` Shepard passes
//   (below): carried unsmoothed from step to step, single-particle pressure spikes fed a
//   growing velocity noise (the 2.5 mm column blew up at 0.45 s). The PPE then solves for
//   p^{n+1} − p̃.
#include <vector>

#include "isph/ParticleSystem.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph {

// `passes` Shepard passes over the material pressure: p_a ← Σ_b V_b W_ab p_b / Σ_b V_b W_ab
// over a and its material neighbours, with the free-surface particles (freeSurface != 0)
// held at p = 0. Returns the material particles' values (size ps.nMaterial); 0 passes
// returns pⁿ as it is. A linear field is kept where the support is full; where it is cut
// (next to a wall, below the free surface) the mean leans towards the neighbours' side.
std::vector<double> smoothedPressure(const ParticleSystem& ps, const Kernel& kernel,
                                     const std::vector<char>& freeSurface, int passes);

}  // namespace isph
