#pragma once
// Renormalised kernel gradients (Randles & Libersky 1996; Bonet & Lok 1999): the paper's
// "renormalized kernel gradient in the case of particle deficiency". With
//   L_a = [ Σ_b V_b ∇_a W_ab ⊗ (x_b − x_a) ]⁻¹,  ∇̃_a W_ab = L_a ∇_a W_ab
// gradients of linear fields are exact near walls and the free surface. Where the
// neighbourhood is too sparse to invert (splash), L_a falls back to the identity.
#include <vector>

#include <Eigen/Core>

#include "isph/ParticleSystem.hpp"

namespace isph {

class KernelGradientCorrection {
 public:
  // Computes L_a for the material particles, identity for the wall and dummy particles (whose
  // gradients nothing takes, and whose neighbour rows hold the material only: NeighbourList.hpp),
  // or for all when `enabled` is false.
  void update(const ParticleSystem& ps, bool enabled, double minDeterminant);

  const Eigen::Matrix3d& operator[](std::size_t a) const { return L_[a]; }
  std::size_t nFallbacks() const { return fallbacks_; }

 private:
  std::vector<Eigen::Matrix3d> L_;
  std::size_t fallbacks_ = 0;
};

}  // namespace isph
