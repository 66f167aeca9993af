#pragma once
// Eq. 11: the projection step u_a = u*_a − (dt/ρ_a) ∇p_a with the renormalised difference
// gradient
//   ∇p_a = L_a Σ_b V_b (p_b − p_a) ∇_a W_ab,
// exact for linear pressure fields, also at the free surface (half support, p given there) and
// next to walls, where p_b is the wall condition of WallBoundaryPressure seen from a. The
// paper prints Eq. 11 in the symmetric form Σ m_b (p_a/ρ_a² + p_b/ρ_b²)∇W, which conserves
// momentum but is inconsistent where the support is cut: a granular layer at rest on a 20°
// slope crept 12.9 mm in 2 s with it (granularAtRest, 5 mm spacing; 0.25 dx allowed), and
// granularSlope's deposit with it moved with the time step (29.6° at maxDeltaT 1e-3, 19.4° at
// 2.5e-4). It was removed with issue 48 (doc/notes/granularStep.md); particle shifting keeps the
// difference form's particle distribution regular.
#include <vector>

#include "isph/discretisation/KernelGradientCorrection.hpp"
#include "isph/ParticleSystem.hpp"

namespace isph {

// ∇p_a of material particle a as Eq. 11 uses it.
Vec3 pressureGradient(const ParticleSystem& ps, const KernelGradientCorrection& L, const std::vector<Vec3>& ustar,
                      const Vec3& g, std::size_t a, double dt);

// Sets ps.cloud.U of the material particles from u* and the pressure (Eq. 11).
void correctVelocity(ParticleSystem& ps, const KernelGradientCorrection& L, const std::vector<Vec3>& ustar,
                     const Vec3& g, double dt);

}  // namespace isph
