#pragma once
// Gradients over material neighbours only, renormalised with the material-only moment
//   M_a = Σ_b∈material V_b (x_b − x_a) ⊗ ∇W_ab,   ∇f_a = M_a⁻ᵀ Σ_b V_b (f_b − f_a) ∇W_ab,
// exact for a linear field of the material even next to a wall or the free surface (where
// the wall particles carry no value of f). Where M_a is too degenerate to invert (a
// splash), the uncorrected sum is used.
#include <Eigen/Core>
#include <vector>

#include "core/Types.hpp"
#include "isph/ParticleSystem.hpp"

namespace isph {

// M_a⁻¹ of material particle a, or the identity where det M_a ≤ minDeterminant.
Eigen::Matrix3d materialMomentInverse(const ParticleSystem& ps, std::size_t a, double minDeterminant);

// ∇p of the material particles (size nMaterial).
std::vector<Vec3> materialPressureGradient(const ParticleSystem& ps, double minDeterminant);

}  // namespace isph
