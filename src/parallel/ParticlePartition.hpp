#pragma once
// What Zoltan partitions a cloud by (decomposePar, the solver's in-memory decomposition and
// its repartitions): each particle's position, but a dummy particle at its wall particle's
// (parent[i], an index into the cloud), so that a dummy always lives on the rank of the wall
// whose normal it reads; and each particle's share of a step's work (weights below). Each
// point is moved by a millionth of a spacing or less, in a direction drawn from its origId:
// particles on a lattice share coordinates, and RCB splits a row of equal coordinates between
// two parts where its kept cut (partOf) would put them all on one side.
#include <vector>

#include "particles/ParticleCloud.hpp"

namespace isph {

// A material particle is a row of both linear systems and of every pair loop; a wall particle
// a row of the kernel correction, the free-surface scan and the wall pressure; a dummy of the
// wall pressure alone.
constexpr double materialWeight = 1.0, wallWeight = 0.15, dummyWeight = 0.05;

double partitionWeight(label kind);

struct PartitionInput {
  std::vector<Vec3> points;
  std::vector<double> weights;
};

// parent: for each dummy particle the index of its wall particle (-1 for the others; a dummy
// without one is placed where it is).
PartitionInput partitionInput(const ParticleCloud& cloud, const std::vector<int>& parent);

// x moved by at most 1e-6 spacing, the same way for the same id (see above).
Vec3 partitionPoint(const Vec3& x, label id, double spacing);

// Below this many material particles per subdomain a rank's halo (the ghosts within two kernel
// supports around it) outweighs the particles it owns: another rank adds communication, not speed.
constexpr long minMaterialPerSubdomain = 100;

// A warning (the run goes on) when a decomposition has more subdomains than its material particles
// make sense of: a subdomain without material particles, or fewer than minMaterialPerSubdomain on
// average; it says how many subdomains would. `materialPerPart`: material particles per subdomain.
void warnIfOverDecomposed(const std::vector<long>& materialPerPart);

// The load (sum of weights) of this rank's particles.
double partitionLoad(const ParticleCloud& cloud);

}  // namespace isph
