#pragma once
// Eq. 6: the intermediate velocity from gravity and the deviatoric (viscous) stress,
//   u*_a = u_a + dt (g + (1/ρ) ∇·s)_a,
// the viscous term in Morris et al.'s (1997) form with s = 2 η D:
//   (1/ρ ∇·(η∇u))_a = Σ_b m_b (η_a+η_b)/(ρ_a ρ_b) (x_ab·∇_a W_ab)/(r_ab²+0.01h²) (u_a − u_b).
// Walls are no-slip (u_w = 0) for the viscous term. Only computed when some material has a
// deviatoric stress (an inviscid fluid runs gravity only).
#include <vector>

#include "isph/ParticleSystem.hpp"

namespace isph {

class IntermediateVelocity {
 public:
  // ustar receives u* for every particle (walls and dummies: 0). Returns the largest
  // magnitude of the viscous acceleration (for the time-step limit).
  static double compute(const ParticleSystem& ps, const MaterialTable& materials, const Vec3& g, double dt,
                        double h, std::vector<Vec3>& ustar);
};

}  // namespace isph
