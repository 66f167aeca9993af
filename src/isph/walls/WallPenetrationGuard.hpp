#pragma once
// The safeguard behind the PPE's no-penetration: a material particle closer than `distance`
// (in dx) to the surface of its nearest wall particle, or behind it, is put back at that
// distance and loses its velocity into the wall. Every activation is counted: a non-zero
// count is a bug or time-step signal, not a feature (numerics.md §3). A particle found
// behind the wall surface (it crossed the wall during the step) is a crossing: counted
// separately, and the first one is described so that the solver can report it.
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
