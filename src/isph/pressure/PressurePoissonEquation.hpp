#pragma once
// The pressure Poisson equation (Eqs. 8 and 10), assembled as A p = b with A = −L (positive
// diagonal, non-positive off-diagonals: the M-matrix sign pattern BoomerAMG expects):
//
//   Σ_b C_ab (p_a − p_b) = m_a S_a,   C_ab = m_a m_b 8/(ρ_a+ρ_b)² (x_ab·∇_a W_ab)/(r_ab²+η²)
//
// (Eq. 10 multiplied by m_a, which makes the matrix symmetric). With θ_a = Σ_b V_b W_ab the
// kernel sum (θ/θ0 = ρ/ρ0) and θ_ref its full-lattice value θ0, the source S_a is
//   densityInvariant (the paper): (θ_ref − θ*_a)/(θ_ref dt²), θ* at the intermediate positions,
//   divergence:                   ∇·u*_a/dt (renormalised difference form),
//   mixed:                        ∇·u*_a/dt + α (θ_ref − θⁿ_a)/(θ_ref dt²).
// Particles whose support reaches the free surface or a wall have a kernel sum that differs
// from θ0 without a density error: below the surface it is short (suction if compared with
// θ0), next to a wall it depends on how the wall particles sit (particleMesh leaves the
// material half a spacing from them: θ is 10-30% high there, and the paper's source then
// blows the first rows off the wall in one step). For them θ_ref = θⁿ_a − β max(θ_lat − 1.01 θ0, 0):
// the change over the step counts, and a share β (`source { relaxation 0.1; }`) of any
// compression beyond the lattice density (1 % dead band) is undone each step. θ_lat is θⁿ_a
// with the wall and dummy particles moved half a spacing back along their wall's normal, onto
// the lattice the material continues (θ_lat = θ0 to 1e-4 for material at rest on a flat wall
// or in a corner). Without this term compaction next to the free surface and walls, where
// p = 0 is near, accumulates step by step: the Bui column lost a third of its area at 5 mm
// and its rods clumped; with it the kernel sum stays within 2 % of θ0 on average. A cut
// support that is also compressed is not seen (θ_lat < θ0 there).
// Unknowns are the material particles that are not on the free surface; free-surface
// particles hold p = 0 (Dirichlet: an identity row each, eliminated from their neighbours'
// rows, so that the matrix has one row per material particle at every step), except, for the materials in keepCompressed
// (granular ones by default: `freeSurface { compressed granular; }`), flagged particles away
// from walls whose kernel sum exceeds θ0 (PpeDirichletParticles.hpp): a compressed particle is no opening to the outside
// but a clump at the surface, which p = 0 could not push apart (numerics.md §2: p = 0 inside a
// granular front takes its strength). For fluids it stays p = 0: at the dam break's front it
// raised the front speed from +5 % to +12 % against the experiment. Wall and dummy particles are not unknowns:
// they carry the Neumann condition of WallBoundaryPressure, whose known increment p_b(a) − p_a
// goes to the right-hand side; in the sums over neighbours they move with particle a.
#include <memory>
#include <vector>

#include "isph/IsphSchemes.hpp"
#include "isph/discretisation/KernelGradientCorrection.hpp"
#include "isph/ParticleSystem.hpp"
#include "linearSolvers/LinearSolver.hpp"

namespace isph {

class PressurePoissonEquation {
 public:
  // `keepCompressed[m]`: flagged particles of material m that are compressed stay unknowns
  // (empty: none do).
  // `tensionCutoff`: p ← max(p, 0) after the solve.
  PressurePoissonEquation(const PpeSettings& settings, bool tensionCutoff, std::unique_ptr<LinearSolver> solver,
                          std::vector<char> keepCompressed = {});

  // Assemble and solve; writes p into ps.cloud.p for the material particles (warm start from
  // it); the walls' pressures follow from them (WallBoundary::update).
  // `ustar` is the intermediate velocity, `freeSurface` the flags of the FreeSurfaceDetector.
  SolverPerformance solve(ParticleSystem& ps, const Kernel& kernel, const KernelGradientCorrection& L,
                          const std::vector<Vec3>& ustar, const std::vector<char>& freeSurface, const Vec3& g, double dt);

  // The last assembled system (for tests and diagnostics).
  const SparseSystem& system() const { return system_; }
  double assemblySeconds() const { return assemblySeconds_; }
  const LinearSolver& solver() const { return *solver_; }
  // The particles were reordered: the solver keeps no preconditioner across it.
  void renumbered() { solver_->rebuildPreconditionerForNextSolve(); }

 private:
  void assemble(const ParticleSystem& ps, const Kernel& kernel, const KernelGradientCorrection& L,
                const std::vector<Vec3>& ustar, const std::vector<char>& freeSurface, const Vec3& g, double dt);

  PpeSettings settings_;
  bool tensionCutoff_;
  std::unique_ptr<LinearSolver> solver_;
  std::vector<char> keepCompressed_;
  SparseSystem system_;
  std::vector<char> dirichlet_;  // per material particle (its row): p held, an identity row
  double assemblySeconds_ = 0;
};

}  // namespace isph
