#pragma once
// Fickian particle shifting (Lind et al. 2012): keeps the particle distribution even, which
// the projection alone does not. δr_a = −D ∇C_a, ∇C_a = Σ_b V_b (1 + 0.2 (W_ab/W(dx))⁴) ∇_a W_ab,
// D = A h u dt, with u (isphSchemes `shifting { speed }`):
//   velocity     |u_a|, as Lind et al. (the default; water): a deposit at rest is never shifted,
//                but a block that slides as a whole is, and it reshuffled slidingBlock's stiff
//                block as it slid (its acceleration +28 % at maxCo 0.2, +13 % at 0.05);
//   deformation  h |γ̇_a|, the speed at which the material deforms across a smoothing length
//                (|γ̇| = √(2 D:D) of the material-only renormalised velocity gradient,
//                deformationSpeed): nothing moving as a whole is shifted (every granular scene:
//                the block −0.3 % / +0.05 % / +0.6 % at dt, dt/2, dt/4). The dam break's surge
//                front ran 13 % fast with it, so water keeps |u|. The RMS of |u_b − u_a| over the
//                support, tried first, rises with a particle's own noise, which the Taylor
//                correction's δr·∇u then fed: the 2.5 mm column at maxCo 0.05 blew up at 0.56 s
//                (doc/notes/granularStep.md).
// |δr| ≤ maxShift·dx. Free-surface
// particles are not shifted, and in effect neither are their neighbours: next to the surface
// the component along −∇C/|∇C| is removed, and δr is parallel to ∇C, so nothing is left (up
// to rounding). A flow a few particles thick lies wholly in that band, and there the
// distribution is left to the PPE and the collision safeguard: with the difference form of
// Eq. 11 granularSlope's sand stream paired up to the collision distance, 0.5 dx
// (doc/notes/granularSlope.md, tutorials/diagnostics/pairs.py), so that case uses the symmetric form
// (VelocityCorrection.hpp), whose pairs repel.
// `shifting { nearSurface pairs; }` (system/isphSchemes; default none) shifts there by the
// pair term alone, δr = −D Σ_b V_b 0.2 max((W_ab/W(dx))⁴ − 1, 0) ∇_a W_ab over material b:
// zero on a lattice and for any neighbour at dx or farther, it pushes apart two particles
// closer than dx along their line. Measured (2026-12-02, one run each, the 8 mm one with a
// draft that differed only in rounding): granularSlope at
// 8 mm, 355 instead of 938 of 2,397 particles closer than 0.6 dx at 7 s, deposit face 22.1°
// instead of 18.8°, 66 % instead of 55 % of the sand on the floor, fastest at 7 s 0.22 m/s
// instead of 1.31; but it spread the column's front along the bed (toe +16.7 % at 2 mm,
// −3.1 % without it) and slowed granularSlope's drain at 12 mm (22 % of the sand left in the
// reservoir at 7 s in two runs, 12 % without), so no case uses it yet. Next to a wall the
// component normal to it is removed. Velocity and pressure are then
// Taylor-corrected, φ ← φ + δr·∇φ, with the gradient over material neighbours only
// (MaterialGradient: walls carry no velocity of the material).
#include <vector>

#include "isph/IsphSchemes.hpp"
#include "sph/kernels/Kernel.hpp"
#include "isph/ParticleSystem.hpp"

namespace isph {

// h |γ̇_a| of material particle a, the strain rate of its material-only renormalised velocity
// gradient (MaterialGradient's moment): how fast the material deforms there, whatever the frame.
double deformationSpeed(const ParticleSystem& ps, const Kernel& kernel, std::size_t a, double correctionMinDeterminant);

struct ShiftingResult {
  double maxShift = 0;  // largest |δr| / dx
  std::size_t capped = 0;
};

ShiftingResult shiftParticles(ParticleSystem& ps, const Kernel& kernel, const std::vector<char>& freeSurface,
                              const ShiftingSettings& settings, double correctionMinDeterminant, bool tensionCutoff,
                              double dt);

}  // namespace isph
