#include "postProcessing/forces/WallStress.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/fields/FieldIO.hpp"

namespace isph {

std::optional<std::vector<SymmTensor>> readDeviatoricStress(const std::filesystem::path& timeDir,
                                                            const std::string& cloudName, std::size_t n) {
  const auto file = timeDir / "lagrangian" / cloudName / "tau";
  if (!std::filesystem::is_regular_file(file)) return std::nullopt;
  return readField<SymmTensor>(file, n);
}

std::optional<std::vector<Vec3>> readWallFriction(const std::filesystem::path& timeDir, const std::string& cloudName,
                                                  std::size_t n) {
  const auto file = timeDir / "lagrangian" / cloudName / "wallFriction";
  if (!std::filesystem::is_regular_file(file)) return std::nullopt;
  return readField<Vec3>(file, n);
}

std::vector<SymmTensor> wallDeviatoricStress(const ParticleCloud& cloud, const std::vector<SymmTensor>& tau,
                                             const NeighbourList& neighbours, const std::vector<char>* selected) {
  const std::size_t n = cloud.size();
  if (tau.size() != n || neighbours.nParticles() != n) {
    fatalError(fmt::format("wallDeviatoricStress: {} particles but {} values of tau and a neighbour list of {}", n,
                           tau.size(), neighbours.nParticles()));
  }
  std::vector<SymmTensor> wallTau(n, SymmTensor::Zero());
  const auto material = static_cast<label>(ParticleKind::material);
  const auto wall = static_cast<label>(ParticleKind::wall);
  const long nl = static_cast<long>(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < nl; ++i) {
    const auto w = static_cast<std::size_t>(i);
    if (cloud.kind[w] != wall || (selected && !(*selected)[w])) continue;
    SymmTensor sum = SymmTensor::Zero();
    double weight = 0;
    for (long k = neighbours.start[w]; k < neighbours.start[w + 1]; ++k) {
      const auto b = static_cast<std::size_t>(neighbours.index[static_cast<std::size_t>(k)]);
      // Only the material in front of the wall (a thin wall's support reaches through it).
      if (cloud.kind[b] != material || (cloud.positions[b] - cloud.positions[w]).dot(cloud.normal[w]) <= 0) continue;
      const double W = neighbours.W[static_cast<std::size_t>(k)];
      sum += W * tau[b];
      weight += W;
    }
    if (weight > 0) wallTau[w] = sum / weight;
  }
  return wallTau;
}

}  // namespace isph
