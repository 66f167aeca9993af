#include "isph/parallel/OwnedParticles.hpp"

#include <algorithm>

#include "parallel/ParticleFields.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

double meanNeighbours(const ParticleSystem& ps) {
  long pairs = 0, particles = 0;
  const auto& nl = ps.neighbours;
  for (std::size_t a = 0; a < std::min(nl.nParticles(), ps.ownMaterial()); ++a) {
    pairs += nl.start[a + 1] - nl.start[a];
    ++particles;
  }
  particles = sumOverRanks(particles);
  return particles > 0 ? static_cast<double>(sumOverRanks(pairs)) / static_cast<double>(particles) : 0.0;
}

std::vector<char> ownedMask(const ParticleSystem& ps) {
  std::vector<char> mask(ps.size());
  for (std::size_t a = 0; a < ps.size(); ++a) mask[a] = ps.isOwned(a);
  return mask;
}

ParticleCloud ownedCloud(const ParticleSystem& ps) {
  ParticleCloud cloud = ps.cloud;
  if (!ps.halo) return cloud;
  std::vector<std::size_t> keep;
  for (std::size_t a = 0; a < ps.size(); ++a) {
    if (ps.isOwned(a)) keep.push_back(a);
  }
  ParticleFields(cloud).keep(keep);
  return cloud;
}

}  // namespace isph
