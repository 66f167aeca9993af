#pragma once
// The safeguard behind the PPE's no-penetration: a material particle closer than `distance`
// (in dx) to the surface of its nearest wall particle, or behind it, is put back at that
// distance and loses its velocity into the wall. Every activation is counted: a non-zero
// count is a bug or time-step signal, not a feature (numerics.md §3). A particle found
// behind the wall surface (it crossed the wall during the step) is a crossing: counted
// separately, and the first one is described so that the solver can report it.
// At a concave corner (a floor and a side or symmetry wall, with the material between them)
// a particle beside the corner is as near to the corner's wall particle, whose normal is one
// wall's, as to the other wall's first particle: the nearest decides, and the other wall's
// plane would go unguarded (the bottom row of an axisymmetric column sank through its floor
// beside the x = 0 wall, doc/notes/threeD.md). So the nearest wall particle's concave partner
// is guarded too: the nearest wall particle b within half a spacing of the nearest distance
// that lies in front of the nearest one's plane (by more than a tenth of a spacing) while the
// nearest lies on or in front of b's plane. A flat wall has no partner (its particles share a
// plane), nor has a convex corner (each particle lies behind the other's plane).
#include <string>

#include "isph/ParticleSystem.hpp"

namespace isph {

struct WallGuardResult {
  std::size_t moved = 0;     // particles put back (crossings included)
  std::size_t crossed = 0;   // particles that were behind a wall surface
  std::string firstCrossing; // which and where, for the log; empty when none crossed
};

// Uses the step's neighbour list.
WallGuardResult guardWallPenetration(ParticleSystem& ps, double distance);

}  // namespace isph
