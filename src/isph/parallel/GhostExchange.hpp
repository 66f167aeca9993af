#pragma once
// The solver's halo exchange (doc/parallel.md): after a loop has computed a field for the
// particles of this rank, exchangeGhosts gives each ghost its owner's value, so that the next
// pair loop that reads the field at a neighbour reads the owner's. A field of all particles
// or of the material particles alone; nothing in a serial run. Collective.
#include <vector>

#include "isph/ParticleSystem.hpp"

namespace isph {

template <class T>
void exchangeGhosts(const ParticleSystem& ps, std::vector<T>& field) {
  if (ps.halo) ps.halo->exchange(field);
}

}  // namespace isph
