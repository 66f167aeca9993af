#pragma once
// An n × n square lattice of material particles at spacing dx (centres at (i + ½, j + ½) dx,
// particle j n + i), 2D, no walls, with its neighbour list built: for tests of the passes
// that need only positions, volumes and neighbours.
#include <algorithm>
#include <vector>

#include "isph/ParticleSystem.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph::test {

// The block without the particles of `removed` (lattice indices j n + i).
inline ParticleSystem latticeBlock(const Kernel& kernel, int n, double dx, const std::vector<int>& removed = {}) {
  ParticleSystem ps;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (std::find(removed.begin(), removed.end(), j * n + i) == removed.end()) {
        ps.cloud.positions.emplace_back((i + 0.5) * dx, (j + 0.5) * dx, 0.0);
      }
    }
  }
  const std::size_t count = ps.cloud.positions.size();
  ps.cloud.normal.assign(count, Vec3::Zero());
  ps.dimension = 2;
  ps.dx = dx;
  ps.nMaterial = count;
  ps.volume.assign(count, dx * dx);
  ps.neighbours.build(ps.cloud.positions, kernel);
  return ps;
}

}  // namespace isph::test
