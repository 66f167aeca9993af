#pragma once
// The force that the material exerts on a set of wall patches, summed over the patches'
// wall particles w (kind wall; the dummies behind them carry no surface):
//
//   pressure part    F_p = Σ_w  p_w A_w (−n_w)
//   deviatoric part  F_d = Σ_w  A_w τ_w·n_w
//   friction part    F_f = Σ_w  A_w t_w
//   total            F   = F_p + F_d + F_f
//   moment           M   = Σ_w (x_w − CofR) × f_w   (each part and the total)
//
// The friction part is for a material that slides on the walls (WallContact::coulombFriction).
// The solver's walls act on such a material by two forces only: the pressure of the wall
// particles (what stops it entering the wall, so p_w carries the whole normal traction) and
// the Coulomb friction (WallFriction); its viscous term leaves the walls out. t_w is the
// traction that friction puts on wall particle w (the field `wallFriction` the solver writes,
// WallFriction::wallTraction). With it given, F = F_p + F_f, and F_d = 0: the material's
// stress next to the wall, τ_w·n_w, is not a force the solver applies there, and adding it
// would break the momentum balance (a block on a 30° bed: F_p = m g cos θ within 1.4 %,
// F_p + A τ·n 87 % above it). On a free-slip patch t_w = 0: such a wall takes no shear.
// Without it (a fluid, which sticks and is sheared by the wall) F_f = 0 and F_d is τ_w·n_w.
// A scene that mixes a sliding and a sticking material on one patch would need the choice
// per wall particle; the field exists only where some material slides, and then holds for
// every wall particle.
//
// Conventions:
//  - n_w is the wall particle's unit normal, pointing out of the solid into the material
//    (as particleMesh writes it). σ·n is then the traction the material applies to the solid,
//    so a pressure p > 0 pushes the wall along −n. Negative (tensile) wall pressures are
//    summed as they are, not clipped.
//  - p is the pressure (mean normal stress, compression positive) that the ISPH solver solves
//    for on the wall particles; τ is the deviatoric stress, tension positive (τ = 2ηD, as the
//    solver's material models), carried to the wall particles by wallDeviatoricStress.
//  - A_w is the surface each wall particle stands for: dx × width in 2D (wall particles lie
//    dx apart along the surface; width = 1 gives the force per metre of width), dx² in 3D.
//    A wall particle at a patch's end or corner also counts dx, so a patch sampled by N
//    particles has an error of order 1/N at its ends.
//  - normal and tangential components use the set's mean normal n̄ = normalised Σ_w n_w
//    (one direction for the whole set: exact for a flat patch, an average for a curved or
//    multi-patch set):
//        normal      F_n = −F·n̄     positive when the material pushes into the structure,
//        tangential  F_t =  F·t̂,    t̂ = n̄ × ẑ in 2D: along the patch in the direction its
//                    chain runs with the material on the left (for a bed with material above,
//                    t̂ = +x); in 3D F_t = |F − (F·n̄) n̄| (magnitude, t̂ = 0).
#include <vector>

#include "core/Types.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

struct PatchForces {
  Vec3 pressure = Vec3::Zero();
  Vec3 deviatoric = Vec3::Zero();
  Vec3 friction = Vec3::Zero();
  Vec3 total = Vec3::Zero();
  Vec3 momentPressure = Vec3::Zero();
  Vec3 momentDeviatoric = Vec3::Zero();
  Vec3 momentFriction = Vec3::Zero();
  Vec3 momentTotal = Vec3::Zero();
  Vec3 meanNormal = Vec3::Zero();  // n̄ (unit; zero when the set has no wall particle or its
                                   // normals cancel, as two facing walls: then F_n = F_t = 0)
  Vec3 tangent = Vec3::Zero();     // t̂ (2D), zero in 3D
  long nWall = 0;                  // wall particles summed
  int dimension = 2;

  double normal(const Vec3& F) const { return 0.0 - F.dot(meanNormal); }  // (never -0)
  double tangential(const Vec3& F) const;
};

struct PatchForceInput {
  const ParticleCloud& cloud;
  std::vector<label> patches;  // patch labels of the set (indices into cloud.properties.patches)
  // τ on the wall particles (wallDeviatoricStress), one per particle; null: no deviatoric part.
  const std::vector<SymmTensor>* wallTau = nullptr;
  // The Coulomb friction traction t_w on the wall particles [Pa] (the solver's wallFriction),
  // one per particle; given: the material slides (F_d = 0, see above); null: F_f = 0.
  const std::vector<Vec3>* wallFriction = nullptr;
  Vec3 CofR = Vec3::Zero();
  double width = 1.0;  // out-of-plane width [m] in 2D (1: per metre); must be 1 in 3D
  // Only the wall particles whose normal n_w lies within 60° of this direction (n_w·f̂ > ½):
  // one face of a structure, e.g. a barrier's upstream face (ForceSet `facing`); zero: all.
  Vec3 facing = Vec3::Zero();
  // A parallel run: this rank's own particles (1) among the cloud's ghosts (0); the sums run
  // over the own wall particles and then over all ranks (a collective call). Null: serial.
  const std::vector<char>* owned = nullptr;
};

// Sums over the wall particles of `in.patches` (those facing `in.facing`, if given).
// FatalError for a patch label out of range, a non-positive spacing or width, or a width
// other than 1 in 3D.
PatchForces patchForces(const PatchForceInput& in);

}  // namespace isph
