#pragma once
// What Zoltan partitions a cloud by (decomposePar, the solver's in-memory decomposition and
// its repartitions): each particle's position, but a dummy particle at its wall particle's
// (parent[i], an index into the cloud), so that a dummy always lives on the rank of the wall
// whose normal it reads; and each particle's share of a step's work (weights below).
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

// parent: for each dummy particle the index of its wall particle (-1 for the others, or
// empty when the cloud has no dummies); FatalError for a dummy without one.
PartitionInput partitionInput(const ParticleCloud& cloud, const std::vector<int>& parent);

// The load (sum of weights) of this rank's particles.
double partitionLoad(const ParticleCloud& cloud);

}  // namespace isph
