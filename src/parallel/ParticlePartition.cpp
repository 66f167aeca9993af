#include "parallel/ParticlePartition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <numeric>

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

Vec3 partitionPoint(const Vec3& x, label id, double spacing) {
  // A fixed pseudo-random direction per id (a multiplicative hash), scaled to 1e-6 spacing.
  auto unit = [id](std::uint64_t salt) {
    std::uint64_t h = (static_cast<std::uint64_t>(id) + 1) * 0x9E3779B97F4A7C15ull ^ salt;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    return static_cast<double>(h >> 11) / 9007199254740992.0 - 0.5;  // [-0.5, 0.5)
  };
  const double scale = 2e-6 * spacing;
  return x + scale * Vec3(unit(1), unit(2), unit(3));
}

PartitionInput partitionInput(const ParticleCloud& cloud, const std::vector<int>& parent) {
  PartitionInput in{cloud.positions, std::vector<double>(cloud.size())};
  const double spacing = cloud.properties.spacing;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    in.weights[i] = partitionWeight(cloud.kind[i]);
    if (cloud.kind[i] == static_cast<label>(ParticleKind::dummy) && i < parent.size() && parent[i] >= 0) {
      if (static_cast<std::size_t>(parent[i]) >= cloud.size()) {
        fatalError(fmt::format("partitionInput: the wall of dummy particle {} is particle {} of {}", i, parent[i],
                               cloud.size()));
      }
      const auto w = static_cast<std::size_t>(parent[i]);
      in.points[i] = partitionPoint(cloud.positions[w], cloud.origId[w], spacing);
    } else {
      in.points[i] = partitionPoint(cloud.positions[i], cloud.origId[i], spacing);
    }
  }
  return in;
}

double partitionLoad(const ParticleCloud& cloud) {
  double load = 0;
  for (const label k : cloud.kind) load += partitionWeight(k);
  return load;
}

void warnIfOverDecomposed(const std::vector<long>& materialPerPart) {
  const auto parts = static_cast<long>(materialPerPart.size());
  const long material = std::accumulate(materialPerPart.begin(), materialPerPart.end(), 0L);
  const auto empty = std::count(materialPerPart.begin(), materialPerPart.end(), 0L);
  if (parts <= 1 || (empty == 0 && material >= minMaterialPerSubdomain * parts)) return;
  warning(fmt::format("{} subdomains for {} material particles ({:.3g} per subdomain, {} with none): more than make "
                      "sense; below {} material particles a subdomain's halo outweighs its own particles. "
                      "numberOfSubdomains {} or fewer in system/decomposeParDict",
                      parts, material, static_cast<double>(material) / static_cast<double>(parts), empty,
                      minMaterialPerSubdomain, std::max(1L, material / minMaterialPerSubdomain)));
}

}  // namespace isph
