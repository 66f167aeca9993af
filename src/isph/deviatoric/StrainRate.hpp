#pragma once
// The rate of deformation of the material particles (the paper's Eqs. 4-5 with the sign
// flipped: D = ½(∇u + ∇uᵀ) = −ε̇, tension positive), its deviatoric part and the shear-rate
// magnitude |γ̇| = √(2 D':D') (= |∂u/∂y| in simple shear).
//
// The velocity gradient is the renormalised SPH difference gradient
//   ∇u_a = Σ_b V_b (u_b − u_a) ⊗ ∇W_ab · M_a⁻¹,  M_a = Σ_b V_b (x_b − x_a) ⊗ ∇W_ab,
// exact for a linear velocity field. The sums run over the particles the material shears
// against: material neighbours always; wall and dummy particles (at rest) only for a
// material that sticks to walls (WallContact::noSlip). A granular material slides on
// walls by Coulomb friction (WallFriction), so walls add no shear to its strain rate.
// For sticking materials M_a⁻¹ is the kernel gradient correction (walls included); for
// sliding ones the material-only moment (MaterialGradient). Where M_a is too degenerate to
// invert (a splash), the uncorrected gradient is used.
#include <vector>

#include "core/Types.hpp"
#include "isph/discretisation/KernelGradientCorrection.hpp"
#include "isph/ParticleSystem.hpp"

namespace isph {

struct StrainRate {
  std::vector<SymmTensor> D;        // deviatoric rate of deformation [1/s], xx xy xz yy yz zz
  std::vector<double> shearRate;    // |γ̇| [1/s]

  // For the material particles (entries beyond nMaterial are left zero), of the velocity
  // field `u` (size ≥ nMaterial; walls are at rest), by default the particles' own.
  void compute(const ParticleSystem& ps, const MaterialTable& materials, const KernelGradientCorrection& correction,
               double minDeterminant);
  void compute(const ParticleSystem& ps, const MaterialTable& materials, const KernelGradientCorrection& correction,
               double minDeterminant, const std::vector<Vec3>& u);
};

// √(2 D:D) of a symmetric tensor in OpenFOAM order.
double shearRateMagnitude(const SymmTensor& D);

}  // namespace isph
