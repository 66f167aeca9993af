#pragma once
// Moving particles to the rank that owns them now (after they crossed a part's boundary, or
// after a new partition), with every field that travels with them (ParticleFields), through
// Zoltan's communication package.
#include <vector>

#include "parallel/ParticleFields.hpp"

namespace isph {

// Sends particle i to rank destination[i] (collective). On return `fields` hold the particles
// that stayed, in their order, then those that arrived, ordered by source rank and within a
// source by their index there. Returns how many arrived.
std::size_t migrateParticles(ParticleFields& fields, const std::vector<int>& destination);

}  // namespace isph
