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

// Whether lattice particle a (index j n + i of the full block) has a full kernel support inside
// the block: at least 3 spacings from every edge (h = 1.3 dx: the support is 2.6 dx).
inline bool inInterior(std::size_t a, int n) {
  const int i = static_cast<int>(a) % n, j = static_cast<int>(a) / n;
  return i >= 3 && i < n - 3 && j >= 3 && j < n - 3;
}

}  // namespace isph::test
