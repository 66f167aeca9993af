#pragma once
// Eq. 6 with the deviatoric term taken implicitly (numerics.md §4): for each velocity
// component, with η lagged from time n (the rigid-plastic viscosity from pⁿ and Dⁿ),
//
//   m_a u*_a/dt + Σ_b κ_ab (u*_a − u*_b) = m_a (u_aⁿ/dt + g) + f_a
//   κ_ab = −m_a m_b (η_a+η_b)/(ρ_a ρ_b) (x_ab·∇_a W_ab)/(r_ab² + 0.01h²) ≥ 0   (Morris form)
//
// The matrix is symmetric positive definite (a mass term plus an M-matrix Laplacian), so
// PCG with BoomerAMG solves it; its settings are `U { ... }` in system/isphSolution, where
// `warmStart` chooses the initial guess: `predictor` (the default), u* = uⁿ + dt g, or
// `lastIncrement`, that plus the last step's viscous increment u* − uⁿ − dt g of the particle
// (scaled by dt/dt_last). In slow, largely rigid flows the increment changes little from step
// to step and the second saves about a fifth of the iterations (column collapse, granular
// slope); in fast flow onto a barrier it costs a seventh more (doc/notes/velocitySolve.md). Walls
// (u_w = 0) add κ_aw to the diagonal for materials that stick to walls, with κ_aw (dt g +
// (u_aⁿ·n) n) on the right: the no-slip term acts on the tangential velocity of time n and
// leaves the wall-normal motion and the gravity increment to the PPE, as the explicit form
// does (a fluid at rest stays exactly at rest). For granular
// material the walls enter instead through the Coulomb friction of WallFriction, which acts
// on the tangential velocity only: a sticking particle adds K_a (I − n_a n_aᵀ) to its block,
// a sliding one the Coulomb force to its right-hand side (WallFrictionActiveSet, whose passes
// settle the stick/slip states). The block couples the components of a particle, so where
// friction acts the components are solved together (one SPD system of dim × N unknowns,
// interleaved; `U { ... }`) and the wall-normal motion is left to the pressure exactly. The time step is then free of the viscous limit ρh²/η: a zone below yield, where
// η reaches etaMax, moves as a rigid body instead of jittering (numerics.md §4).
// The cross term ∇·(η ∇uᵀ), non-zero where η varies, is neglected (as in Morris's form).
#include <array>
#include <memory>
#include <vector>

#include "isph/ParticleSystem.hpp"
#include "isph/walls/WallFriction.hpp"
#include "isph/walls/WallFrictionActiveSet.hpp"
#include "linearSolvers/LinearSolver.hpp"

namespace isph {

struct StepState;

class ImplicitViscousStep {
 public:
  // One solver per component (their AMG set-ups are kept apart), configured from solverDict.
  // frictionPasses: at most this many solves per step to settle the bed friction (≥ 1).
  ImplicitViscousStep(const Dictionary& solverDict, int dimension, int frictionPasses);
  ~ImplicitViscousStep();

  // u* for the material particles (walls and dummies: 0); one performance per component.
  std::vector<SolverPerformance> solve(const ParticleSystem& ps, const MaterialTable& materials,
                                       const std::vector<double>& eta, const WallFriction* friction, const Vec3& g,
                                       double dt, double h, std::vector<Vec3>& ustar);

  // The last solve()'s own assembly: the scalar matrix and, each stick/slip pass, the coupled one
  // (the solvers' hand-over to hypre is in their SolverPerformance).
  double assemblySeconds() const { return assemblySeconds_; }
  // The material particles were reordered: no solver keeps a preconditioner across it.
  void renumbered();
  // Over the velocity solvers (the components' and the coupled one): solves and hierarchies.
  int solvesDone() const;
  int preconditionersBuilt() const;
  // Over the run: the solves with bed friction, how many of them settled, and their passes.
  int frictionSolves() const { return frictionSolves_; }
  int frictionSolvesSettled() const { return frictionSettled_; }
  int frictionPassesDone() const { return frictionPassesDone_; }
  int maxFrictionPasses() const { return maxFrictionPasses_; }
  // What the solve carries to the next step, by origId (the active set's kept stick/slip
  // states, the warm start's increments): into and out of a restart's StepState.
  void saveState(StepState& state) const;
  void restoreState(const StepState& state);
  // The Coulomb force of the walls on each material particle in the last solve [N, per metre
  // in 2D]: tangential, zero off the friction walls; empty when that solve had no friction.
  const std::vector<Vec3>& frictionForce() const { return frictionForce_; }

 private:
  // The components together, with the bed drag K_a (I − n nᵀ) in each particle's block.
  void assembleCoupled(int dim, const std::vector<Vec3>& rhs);
  // The viscous increment u* − uⁿ − dt g of each material particle, by origId: the next
  // step's warm start.
  void keepIncrement(const ParticleSystem& ps, double dt, const Vec3& g, const std::vector<Vec3>& ustar);

  std::vector<std::unique_ptr<LinearSolver>> solvers_;
  std::unique_ptr<LinearSolver> coupledSolver_;
  SparseSystem system_;
  SparseSystem coupled_;
  double assemblySeconds_ = 0;
  int maxFrictionPasses_ = 4;
  WallFrictionActiveSet activeSet_;
  int lastPasses_ = 0;
  bool lastSettled_ = true;
  bool warmFromLastIncrement_ = false;  // U { warmStart lastIncrement; }
  std::vector<Vec3> keptIncrement_;
  double keptDt_ = 0;
  std::vector<Vec3> frictionForce_;
  int frictionSolves_ = 0, frictionSettled_ = 0, frictionPassesDone_ = 0;
};

}  // namespace isph
