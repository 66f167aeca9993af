#pragma once
// The particles a rank owns in a ParticleSystem of own and ghost particles (ParticleSystem.hpp:
// each kind's own particles first, then its ghosts): what a parallel run writes and reports. In
// a serial run (no halo) every particle is owned and each function returns the whole.
#include <vector>

#include "isph/ParticleSystem.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

// The mean number of neighbours of the own material particles over all ranks (collective): the
// rows the method works on (a wall or dummy particle's holds its material neighbours only,
// NeighbourList.hpp).
double meanNeighbours(const ParticleSystem& ps);

// Which particles are this rank's own (1) or ghosts (0); all 1 in a serial run.
std::vector<char> ownedMask(const ParticleSystem& ps);

// The own particles' entries of a per-particle field (all of it in a serial run), for output.
template <class T>
std::vector<T> ownedValues(const ParticleSystem& ps, const std::vector<T>& field) {
  if (!ps.halo) return field;
  std::vector<T> out;
  for (std::size_t a = 0; a < field.size(); ++a) {
    if (ps.isOwned(a)) out.push_back(field[a]);
  }
  return out;
}
// The own particles as a cloud, for output.
ParticleCloud ownedCloud(const ParticleSystem& ps);

}  // namespace isph
