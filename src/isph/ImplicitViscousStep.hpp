#pragma once
// Eq. 6 with the deviatoric term taken implicitly (numerics.md §4): for each velocity
// component, with η lagged from time n (the rigid-plastic viscosity from pⁿ and Dⁿ),
//
//   m_a u*_a/dt + Σ_b κ_ab (u*_a − u*_b) = m_a (u_aⁿ/dt + g) + f_a
//   κ_ab = −m_a m_b (η_a+η_b)/(ρ_a ρ_b) (x_ab·∇_a W_ab)/(r_ab² + 0.01h²) ≥ 0   (Morris form)
//
// The matrix is symmetric positive definite (a mass term plus an M-matrix Laplacian), so
// PCG with BoomerAMG solves it; its settings are `U { ... }` in system/isphSolution. Walls
// (u_w = 0) add κ_aw to the diagonal for materials that stick to walls, with κ_aw (dt g +
// (u_aⁿ·n) n) on the right: the no-slip term acts on the tangential velocity of time n and
// leaves the wall-normal motion and the gravity increment to the PPE, as the explicit form
// does (a fluid at rest stays exactly at rest). For granular
// material the walls enter instead through the Coulomb drag K_a of WallFriction, which acts
// on the tangential velocity only: its normal part is put back on the right with the
// explicit predictor ũ = uⁿ + dt g, so the drag leaves the wall-normal motion to the
// pressure. The time step is then free of the viscous limit ρh²/η: a zone below yield, where
// η reaches etaMax, moves as a rigid body instead of jittering (numerics.md §4).
// The cross term ∇·(η ∇uᵀ), non-zero where η varies, is neglected (as in Morris's form).
#include <array>
#include <memory>
#include <vector>

#include "isph/ParticleSystem.hpp"
#include "isph/WallFriction.hpp"
#include "linearSolvers/LinearSolver.hpp"

namespace isph {

class ImplicitViscousStep {
 public:
  // One solver per component (their AMG set-ups are kept apart), configured from solverDict.
  ImplicitViscousStep(const Dictionary& solverDict, int dimension);
  ~ImplicitViscousStep();

  // u* for the material particles (walls and dummies: 0); one performance per component.
  std::vector<SolverPerformance> solve(const ParticleSystem& ps, const MaterialTable& materials,
                                       const std::vector<double>& eta, const WallFriction* friction, const Vec3& g,
                                       double dt, double h, std::vector<Vec3>& ustar);

  double assemblySeconds() const { return assemblySeconds_; }
  static constexpr int maxFrictionPasses = 4;

 private:
  std::vector<std::unique_ptr<LinearSolver>> solvers_;
  SparseSystem system_;
  double assemblySeconds_ = 0;
};

}  // namespace isph
