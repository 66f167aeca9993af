#pragma once
// The pressure Poisson equation's closed regions (PressurePoissonEquation.cpp,
// pinClosedRegions) in a parallel run: a connected group of unknowns that touches no
// Dirichlet particle (a completely filled container) has its pressure pinned to 0 at one
// particle, and such a group may span ranks. Each rank joins its own unknowns into groups
// (union-find), then the groups take, through the halo, the smallest global row and "anchored"
// of the groups they touch on other ranks, until nothing changes on any rank (a few rounds:
// one per rank boundary a group crosses). The pinned particle is the group's smallest global
// row (on one rank, the first particle, as the serial search).
#include <vector>

#include "isph/ParticleSystem.hpp"

namespace isph {

// As pinClosedRegions: marks in `flags` the pinned particle of every group of unknowns
// (`dirichlet` 0) without a particle that touchesDirichlet; returns their number over all
// ranks (collective). The flags of ghosts are their owners' on return.
int pinClosedRegionsAcrossRanks(const ParticleSystem& ps, const std::vector<char>& touchesDirichlet,
                                std::vector<char>& flags, const std::vector<char>& dirichlet);

}  // namespace isph
