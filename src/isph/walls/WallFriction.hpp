#pragma once
// Coulomb friction between a granular material and the wall patches (the paper: "the
// tangential drag force is equated to the normal reaction multiplied by the wall frictional
// coefficient"; numerics.md §3). Each wall particle w of a patch with friction angle δ > 0
// can carry a tangential force up to
//
//   T_w = tan δ · σ_w · A_w,   σ_w = p_w + ½ ρ max(−g·n_w, 0) dx  (where p_w > 0),  A_w = dx^(d−1),
//
// shared among its material neighbours c in proportion to W_cw. So material particle a
// has the friction capacity F_a = Σ_w T_w W_aw / Σ_c W_cw [N, per metre in 2D] along the
// mean wall normal n_a, and the sum over the material is exactly tan δ × the normal force.
// The half layer in σ_w is the weight that the free-surface condition leaves out: p = 0 holds
// at the centres of the surface particles, half a spacing below the real surface, so the wall
// pressure under a layer of n particles is that of n − ½ (without it a one-particle sheet, all
// free surface, would press on the bed with half its weight and slide too far; the
// rigid-plastic model adds the same half layer to its strength).
//
// `wallFriction { normalForce hydrostatic; }` (system/isphSchemes) takes σ_w instead from the
// material in front of w carried to it hydrostatically, the Shepard mean of
// max(p_a + ρ_a g·(x_w − x_a), 0), plus the same half layer: without the normal condition's
// ρ u*·n/dt r_n of the wall pressure (WallBoundaryPressure.hpp), which turns a particle's
// normal velocity into pressure in proportion to its distance r_n from the wall. A fast thin
// stream (granularSlope) rattles against its bed; the pressure answers each approach and not
// each departure (where the material is at p = 0 it may leave freely), so the walls' pressure
// under it averages several times its weight and the friction brakes the stream (doc/notes/
// granularSlope.md). The material's own pressure p_a, which the PPE sets with that condition, still
// carries impacts and the lithostatic load. Measured on granularSlope at 12 mm (one run): the
// stream's bed friction fell from 1.15-2.81 to 0.60-0.74 times its weight normal to the bed,
// but the deposit came out flatter; no case uses it (doc/notes/granularSlope.md).
//
// Only materials with WallContact::coulombFriction feel it (a fluid sticks instead); a
// patch without a friction angle is a free-slip wall for them.
//
// Two ways to apply it, one per treatment of the viscous term:
// - explicit: the tangential velocity loses dt F_a/m_a, capped so that the step cannot
//   reverse it (a particle that would reverse sticks);
// - implicit (inside the semi-implicit viscous solve): the Coulomb force F_a against the
//   slip while |u_t| > u_slip, a stiff drag (F_a/u_slip) u_t that holds the particle below
//   it, each particle's stick/slip state settled by the active-set passes of
//   WallFrictionActiveSet.
#include <vector>

#include "core/Types.hpp"
#include "isph/IsphSchemes.hpp"
#include "isph/ParticleSystem.hpp"

namespace isph {

class WallFriction {
 public:
  // Active only if some patch has a friction angle and some material slides on walls.
  WallFriction(const ParticleSystem& ps, const MaterialTable& materials, const Vec3& gravity, double slipSpeed,
               FrictionNormal normalStress = FrictionNormal::wallPressure);

  bool active() const { return active_; }
  // Some material slides on walls (whether or not any patch has friction).
  bool slidingMaterial() const { return anySlides_; }
  double slipSpeed() const { return slipSpeed_; }

  // Capacities and normals from the current positions and wall pressures.
  void update(const ParticleSystem& ps);

  double capacity(std::size_t a) const { return capacity_[a]; }
  const Vec3& normal(std::size_t a) const { return normal_[a]; }

  // The tangential part of u relative to the wall next to a.
  Vec3 tangential(std::size_t a, const Vec3& u) const { return u - normal_[a] * normal_[a].dot(u); }
  // The explicit capped update of the material velocities u (size ≥ nMaterial); `applied`
  // (if given) receives the friction force on each material particle, m_a Δu_a/dt.
  void applyExplicit(const ParticleSystem& ps, double dt, std::vector<Vec3>& u,
                     std::vector<Vec3>* applied = nullptr) const;

  // The traction the material exerts on each wall particle through the friction [Pa: force
  // per A_w = dx^(d−1), the force per metre of width in 2D]: the reaction to the forces f_a of the walls
  // on the material (`onMaterial`, per material particle, from the step just taken), each
  // shared among a's friction-wall neighbours w in proportion to W_aw, as its capacity was
  // gathered:  t_w = −Σ_a f_a W_aw / (A_w Σ_w' W_aw').  So Σ_w A_w t_w = −Σ_a f_a exactly
  // (Newton's third law). Size ps.size(); zero but on friction-wall particles. Uses the
  // neighbour list of the step (call before it is rebuilt).
  std::vector<Vec3> wallTraction(const ParticleSystem& ps, const std::vector<Vec3>& onMaterial) const;

 private:
  bool active_ = false;
  bool anySlides_ = false;
  double slipSpeed_ = 0;
  Vec3 gravity_ = Vec3::Zero();
  FrictionNormal normalStress_ = FrictionNormal::wallPressure;
  std::vector<double> tanDelta_;   // per patch
  std::vector<char> slides_;       // per material: coulombFriction
  std::vector<double> capacity_;   // F_a
  std::vector<Vec3> normal_;       // n_a
};

}  // namespace isph
