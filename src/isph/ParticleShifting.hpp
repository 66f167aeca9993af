#pragma once
// Fickian particle shifting (Lind et al. 2012): keeps the particle distribution even, which
// the projection alone does not. δr_a = −D ∇C_a, ∇C_a = Σ_b V_b (1 + 0.2 (W_ab/W(dx))⁴) ∇_a W_ab,
// D = A h |u_a| dt (so a resting deposit is never shifted). At and next to the free surface
// the component normal to it is removed; |δr| ≤ maxShift·dx. Velocity and pressure are then
// Taylor-corrected, φ ← φ + δr·∇φ, with the gradient over material neighbours only
// (MaterialGradient: walls carry no velocity of the material).
#include <vector>

#include "isph/IsphSchemes.hpp"
#include "sph/kernels/Kernel.hpp"
#include "isph/ParticleSystem.hpp"

namespace isph {

struct ShiftingResult {
  double maxShift = 0;  // largest |δr| / dx
  std::size_t capped = 0;
};

ShiftingResult shiftParticles(ParticleSystem& ps, const Kernel& kernel, const std::vector<char>& freeSurface, const IsphSchemes& schemes, double dt);

}  // namespace isph
