#include "postProcessing/sampling/RunOut.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace isph {

Vec3 heightAxis(const Vec3& direction) {
  const Vec3 e = direction.normalized();
  const Vec3 n(-e.y(), e.x(), 0.0);  // z × e
  return n.norm() > 1e-12 ? Vec3(n.normalized()) : Vec3::UnitY();
}

std::optional<double> runOut(const ParticleCloud& cloud, const RunOutSpec& spec) {
  const Vec3 e = spec.direction.normalized();
  const Vec3 n = heightAxis(e);
  const double dx = cloud.properties.spacing;
  std::vector<std::size_t> candidates;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != label(ParticleKind::material)) continue;
    if (std::abs((cloud.positions[i] - spec.origin).dot(n)) <= spec.maxHeight) candidates.push_back(i);
  }
  // Farthest first; the neighbour check then touches only the few particles at the front.
  std::sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
    return cloud.positions[a].dot(e) > cloud.positions[b].dot(e);
  });
  const double reach2 = 2.25 * dx * dx;
  for (const std::size_t i : candidates) {
    int neighbours = 0;
    for (std::size_t j = 0; j < cloud.size() && neighbours < spec.minNeighbours; ++j) {
      neighbours += j != i && cloud.kind[j] == label(ParticleKind::material) &&
                    (cloud.positions[j] - cloud.positions[i]).squaredNorm() < reach2;
    }
    if (neighbours >= spec.minNeighbours) return (cloud.positions[i] - spec.origin).dot(e) + 0.5 * dx;
  }
  return std::nullopt;
}

}  // namespace isph
