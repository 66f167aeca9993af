#include "parallel/ParticlePartition.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

double partitionWeight(label kind) {
  switch (static_cast<ParticleKind>(kind)) {
    case ParticleKind::material: return materialWeight;
    case ParticleKind::wall: return wallWeight;
    case ParticleKind::dummy: return dummyWeight;
  }
  return materialWeight;
}

PartitionInput partitionInput(const ParticleCloud& cloud, const std::vector<int>& parent) {
  PartitionInput in{cloud.positions, std::vector<double>(cloud.size())};
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    in.weights[i] = partitionWeight(cloud.kind[i]);
    if (cloud.kind[i] != static_cast<label>(ParticleKind::dummy)) continue;
    if (i >= parent.size() || parent[i] < 0 || static_cast<std::size_t>(parent[i]) >= cloud.size()) {
      fatalError(fmt::format("partitioning cloud '{}': dummy particle {} (origId {}) has no wall particle", cloud.name,
                             i, cloud.origId[i]));
    }
    in.points[i] = cloud.positions[static_cast<std::size_t>(parent[i])];
  }
  return in;
}

double partitionLoad(const ParticleCloud& cloud) {
  double load = 0;
  for (const label k : cloud.kind) load += partitionWeight(k);
  return load;
}

}  // namespace isph
