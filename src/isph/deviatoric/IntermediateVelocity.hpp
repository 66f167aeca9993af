#pragma once
// Eq. 6, explicit: the intermediate velocity from gravity and the deviatoric (viscous)
// stress at time n,
//   u*_a = u_a + dt (g + (1/ρ) ∇·s)_a,
// the deviatoric term in Morris et al.'s (1997) form with s = 2 η D:
//   (1/ρ ∇·(η∇u))_a = Σ_b m_b (η_a+η_b)/(ρ_a ρ_b) (x_ab·∇_a W_ab)/(r_ab²+0.01h²) (u_a − u_b),
// η per particle from its material (EffectiveViscosity). Walls (u_w = 0) enter the sum for
// materials that stick to walls; a granular material slides, with Coulomb friction applied
// afterwards (WallFriction::applyExplicit). The semi-implicit alternative is
// ImplicitViscousStep. Stable only below the viscous limit dt ≤ C_ν ρ h²/η.
#include <vector>

#include "core/Types.hpp"
#include "isph/ParticleSystem.hpp"

namespace isph {

class IntermediateVelocity {
 public:
  // ustar receives u* for every particle (walls and dummies: 0). eta is empty for an
  // inviscid scene (gravity only). Returns the largest viscous acceleration.
  static double compute(const ParticleSystem& ps, const MaterialTable& materials, const std::vector<double>& eta,
                        const Vec3& g, double dt, double h, std::vector<Vec3>& ustar);
};

}  // namespace isph
