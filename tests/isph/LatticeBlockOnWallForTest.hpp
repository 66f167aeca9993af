#pragma once
// An n × n square lattice of material particles at spacing dx (centres at (i + ½, j + ½) dx,
// particle j n + i, as in LatticeBlockForTest.hpp) resting on a flat wall: a row of n wall
// particles on the wall surface y = 0 at x = (i + ½) dx (particles n² + i) and `dummyLayers`
// rows of dummy particles below it at y = −dx, −2dx, ... (each dummy extends the wall particle
// above it). 2D; every particle has the volume dx², the walls the material's density; the
// neighbour list is built. Material labels, velocities and pressures are left to the test.
#include <vector>

#include "isph/ParticleSystem.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph::test {

inline ParticleSystem latticeBlockOnWall(const Kernel& kernel, int n, double dx, double rho,
                                         int dummyLayers = 2) {
  ParticleSystem ps;
  auto& x = ps.cloud.positions;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) x.emplace_back((i + 0.5) * dx, (j + 0.5) * dx, 0.0);
  for (int i = 0; i < n; ++i) x.emplace_back((i + 0.5) * dx, 0.0, 0.0);
  for (int l = 1; l <= dummyLayers; ++l)
    for (int i = 0; i < n; ++i) x.emplace_back((i + 0.5) * dx, -l * dx, 0.0);
  const std::size_t count = x.size();
  ps.dimension = 2;
  ps.dx = dx;
  ps.nMaterial = static_cast<std::size_t>(n * n);
  ps.nWall = static_cast<std::size_t>(n);
  ps.nDummy = count - ps.nMaterial - ps.nWall;
  ps.cloud.normal.assign(count, Vec3::Zero());
  for (std::size_t a = ps.nMaterial; a < ps.dummyBegin(); ++a) ps.cloud.normal[a] = Vec3(0, 1, 0);
  ps.parentWall.assign(count, -1);
  for (std::size_t d = ps.dummyBegin(); d < count; ++d)
    ps.parentWall[d] =
        static_cast<int>(ps.nMaterial + (d - ps.dummyBegin()) % static_cast<std::size_t>(n));
  ps.rho.assign(count, rho);
  ps.wallRho = rho;
  ps.volume.assign(count, dx * dx);
  ps.neighbours.build(x, kernel);
  return ps;
}

}  // namespace isph::test
