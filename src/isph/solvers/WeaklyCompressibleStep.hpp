#pragma once
// Explicit weakly-compressible SPH (isphSchemes `method wcsph;`): the approach the paper
// argues against, as a baseline inside the same solver. It shares the projection method's
// particles, neighbour list, kernels, rheology (the same regularised rigid-plastic η,
// explicit as IntermediateVelocity), Coulomb wall friction and force routine; only the
// pressure and the walls' part in it differ. Per particle (Monaghan 1994; Bui et al. 2008 for
// soil):
//
//   p_a = c0² (ρ_a − ρ0_a)                linear equation of state (p ≥ 0 with the tension
//                                          cut-off, and always on the walls)
//   dρ_a/dt = Σ_b m_b (u_a − u_b)·∇_a W_ab + δ h c0 Σ_b 2 ψ_ab (x_ab·∇_a W_ab)/(r² + 0.01 h²) V_b
//             continuity, for the wall and dummy particles too (at rest), and δ-SPH density
//             diffusion within a material, ψ_ab = (ρ_a − ρ_b) − ρ0 g·x_ab/c0², the
//             hydrostatic density difference taken out (Fourtakas et al. 2019)
//   du_a/dt = −Σ_b m_b (p_a/ρ_a² + p_b/ρ_b²) ∇_a W_ab    symmetric pressure force over material,
//             wall and dummy neighbours
//             − Σ_b m_b Π_ab ∇_a W_ab                    Monaghan's artificial viscosity,
//             Π_ab = −α h c0 (u_ab·x_ab)/(ρ̄_ab (r² + 0.01 h²)) for approaching material pairs
//             + g + (1/ρ) ∇·s                           as in Eq. 6 (IntermediateVelocity)
//
// The walls are dynamic boundary particles (Crespo et al. 2007, DualSPHysics): wall and
// dummy particles keep their places and carry a density from the continuity equation, so a
// wall pushes back as material compresses against it, also in a corner that the dummy layers
// leave open. Their own pressures act only in these sums: the pressure written on the walls,
// which the force routine integrates and the Coulomb friction is limited by, is the material's
// extrapolated to the wall line (WallBoundaryPressure for a material at rest), as in the
// projection method. (Tried first and rejected: wall pressures extrapolated from the material as the
// projection does, p_b = p_a + ρ g·(x_b − x_a) (Adami et al. 2012). In the symmetric form a
// material particle in such a corner is pushed into it, more the higher its pressure, and
// the tank at rest blew up at its corners; the renormalised difference form of Eq. 11 was
// exact at rest but unstable in the explicit step, its disorder growing ~8 % per step.) They
// start from the hydrostatic extrapolation of the material's pressure.
//
// Advanced by symplectic Euler (u first, then x with the new u, and ρ with the rate at time
// n). The time step is the acoustic one, dt ≤ maxCo h/(c0 + |u|max), besides the force and
// the explicit viscous limits. The densities are the state: every time directory holds them
// (field rho, all particles), so that a restart continues the run; a case without it (from
// particleMesh, or from a projection run) starts from ρ = ρ0 + p/c0².
#include <utility>
#include <vector>

#include "core/Types.hpp"
#include "isph/IsphSchemes.hpp"
#include "isph/ParticleSystem.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph {

class WeaklyCompressibleStep {
 public:
  // c0 [m/s] from the schemes (already resolved from the scene by the caller).
  WeaklyCompressibleStep(const WcsphSettings& settings, bool tensionCutoff, double soundSpeed);

  double soundSpeed() const { return c0_; }
  // ρ from the pressures of all particles (the start and a restart).
  void initialiseDensity(const ParticleSystem& ps);
  // The densities of a restart (field rho of the time directory), in the particles' order.
  void setDensity(std::vector<double> rho) { density_ = std::move(rho); }
  const std::vector<double>& density() const { return density_; }
  // Follows the cell reordering of the material particles (order[new] = old).
  void permute(const std::vector<int>& order);
  // p = c0² (ρ − ρ0) of particle a (walls: p ≥ 0).
  double pressure(const ParticleSystem& ps, std::size_t a) const;
  // ps.cloud.p of the material particles from their densities (the walls' entries are the
  // pressures at the wall line, extrapolated from the material, which forces and friction use).
  void updatePressure(ParticleSystem& ps) const;
  // dρ/dt of every particle at the current state (continuity; diffusion in the material).
  std::vector<double> densityRate(const ParticleSystem& ps, const Kernel& kernel, const Vec3& g, double h) const;
  // −∇p/ρ of material particle a in the symmetric form, walls and dummies included.
  Vec3 pressureForce(const ParticleSystem& ps, const Kernel& kernel, std::size_t a) const;
  // (1/ρ_a) ∇·s of material particle a for elastic-plastic materials (ElasticPlasticStress), in
  // the symmetric form Σ_b m_b (s_a/ρ_a² + s_b/ρ_b²)·∇_a W_ab over material pairs; a wall or dummy
  // b mirrors the material's deviatoric traction (s_b = s_a) along the wall normal only: the
  // walls take the normal stress, the tangential traction is the Coulomb friction's.
  Vec3 deviatoricForce(const ParticleSystem& ps, const Kernel& kernel, const std::vector<SymmTensor>& s,
                       std::size_t a) const;
  // The artificial-viscosity acceleration of material particle a.
  Vec3 artificialViscosity(const ParticleSystem& ps, double h, std::size_t a) const;
  void advanceDensity(const std::vector<double>& rate, double dt);
  // The largest |ρ/ρ0 − 1| of the material (the weak compressibility that c0 allows), and the
  // largest compression ρ/ρ0 − 1 with the particle that has it.
  double maxDensityVariation(const ParticleSystem& ps) const;
  std::pair<double, std::size_t> maxCompression(const ParticleSystem& ps) const;
  // A compression beyond this stops the run: the method assumes |Δρ/ρ0| of order (u/c0)² ≈ 1 %
  // (healthy runs of the validation cases stay below 2.5 %; the unstable designs of the walls
  // went to 23-60 % before they blew up).
  static constexpr double maxAllowedCompression = 0.10;

 private:
  double c0_ = 0;
  double delta_ = 0;
  double alpha_ = 0;
  bool tensionCutoff_ = true;
  std::vector<double> density_;  // ρ of every particle (material | wall | dummy)
};

// The default sound speed: 10x the expected peak speed, the larger of a free fall over the
// scene's height, sqrt(2 |g| H) with H the extent of all particles along gravity, and the
// fastest initial material speed. 0 for a scene at rest without gravity.
double defaultSoundSpeed(const ParticleSystem& ps, const Vec3& g);

}  // namespace isph
