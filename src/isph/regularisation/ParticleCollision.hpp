#pragma once
// The minimum distance between material particles: the safeguard behind the PPE against
// clumping, in the manner of the collision model of MPS (Koshizuka & Oka 1996; Lee et al.
// 2011). The PPE holds p = 0 on free-surface particles, so two of them (or a surface particle
// and its neighbour) feel no pressure when they approach, and the density-invariant source
// constrains kernel sums, not distances: a shearing granular flow lines its particles up in
// pairs closer than half a spacing, and the deposit loses volume (measured: a third of the
// Bui column's area at 5 mm spacing).
//
// After the position update, every pair a, b of material particles closer than d = distance
// × dx is taken as a perfectly inelastic contact: each particle moves half of the overlap
// away from the other along the line of centres, and the pair loses its approaching relative
// normal velocity, shared in proportion to the masses, so momentum is conserved. Each
// particle gathers the corrections of all its contacts from the positions at the start of
// the pass (it writes only its own data). The count of particles moved is reported: it is a
// diagnostic of the scheme, not part of the physics.
#include "isph/ParticleSystem.hpp"

namespace isph {

struct CollisionResult {
  std::size_t moved = 0;  // material particles that had at least one contact
};

// Uses the step's neighbour list; distance in dx (0: off).
CollisionResult separateCloseParticles(ParticleSystem& ps, double distance);

}  // namespace isph
