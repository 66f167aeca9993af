#pragma once
// Eq. 11: the projection step u_a = u*_a − (dt/ρ_a) ∇p_a with the renormalised difference
// gradient
//   ∇p_a = L_a Σ_b V_b (p_b − p_a) ∇_a W_ab,
// exact for linear pressure fields, also at the free surface (half support, p = 0 there) and
// next to walls, where p_b is the wall condition of WallBoundaryPressure seen from a. The
// symmetric form Σ m_b (p_a/ρ_a² + p_b/ρ_b²)∇W conserves momentum but is inconsistent where
// the support is cut, which leaves an error of order g dt/2 on every surface particle;
// particle shifting keeps the difference form's particle distribution regular.
// The paper writes Eq. 11 in the symmetric form, and `pressureGradient symmetric;`
// (system/isphSchemes) uses it: its pairs repel under pressure, which the difference form's
// do not (a uniform pressure has no gradient). Where shifting cannot act, in a stream a few
// particles thick, the difference form lets particles pair up to the collision distance and
// the pairs then read as compression (granularSlope jammed: doc/notes/granularSlope.md). The
// symmetric form is not exact for a linear pressure: a granular layer at rest on a 20° slope
// crept 12.9 mm in 2 s with it (granularAtRest, 5 mm spacing; 0.25 dx allowed), so it is not
// the default.
#include <vector>

#include "isph/KernelGradientCorrection.hpp"
#include "isph/ParticleSystem.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph {

// ∇p_a of material particle a as Eq. 11 uses it.
Vec3 pressureGradient(const ParticleSystem& ps, const KernelGradientCorrection& L, const std::vector<Vec3>& ustar,
                      const Vec3& g, std::size_t a, double dt);

// Eq. 11 of the incremental projection: u = u* − (dt/ρ)∇δp with δp = p^{n+1} − pⁿ per
// material particle and the walls' condition on the increment.
void correctVelocityIncrement(ParticleSystem& ps, const KernelGradientCorrection& L, const std::vector<Vec3>& ustar,
                              const std::vector<double>& increment, double dt);

// −∇p_a/ρ_a in the symmetric (momentum-conserving) form −Σ_b m_b (p_a/ρ_a² + p_b/ρ_b²)∇_a W_ab,
// walls with the condition of WallBoundaryPressure for `ustar`: the lagged pressure force of
// the incremental projection. Pairs of material particles exchange equal and opposite
// forces, so the pressure inside a zone that moves as a rigid body exerts no net force on it
// (the difference form of Eq. 11 is not conservative, and in such a zone, where the pressure
// is carried from step to step, its error would act for ever). A wall pair pushes along the
// wall normal only (the tangential traction is the friction's); `frictionReaction`, if given,
// gets the force [N, per metre in 2D] of the friction walls' pairs on a: its normal reaction,
// which WallFriction then limits the tangential traction by.
Vec3 laggedPressureForce(const ParticleSystem& ps, const Kernel& kernel, const std::vector<Vec3>& ustar,
                         const Vec3& g, std::size_t a, double dt, Vec3* frictionReaction = nullptr);

// Sets ps.cloud.U of the material particles from u* and the pressure: Eq. 11 with the
// renormalised difference gradient, or, with `symmetric`, in the paper's symmetric form
// (laggedPressureForce of p^{n+1}).
void correctVelocity(ParticleSystem& ps, const KernelGradientCorrection& L, const std::vector<Vec3>& ustar,
                     const Vec3& g, double dt, const Kernel* symmetric = nullptr);

}  // namespace isph
