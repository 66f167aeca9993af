#pragma once
// Scenes for the parallel layer's tests: a lattice of particles that every rank can build
// whole (the serial reference), of which each rank keeps a share.
#include <gtest/gtest.h>

#include <vector>

#include "parallel/Reduce.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph::test {

// An nx × ny (× nz) lattice of spacing dx, slightly disturbed (so that no two distances tie),
// with every field a function of the particle's origId (its index in the lattice): a material
// block whose bottom row is wall particles and, below them, a row of dummy particles.
inline ParticleCloud latticeCloud(int nx, int ny, int nz, double dx) {
  ParticleCloud c;
  c.properties.materials = {"sand"};
  c.properties.patches = {{"bed", 30.0}};
  c.properties.dimension = nz > 1 ? 3 : 2;
  c.properties.spacing = dx;
  label id = 0;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i, ++id) {
        const double wobble = 0.05 * dx * std::sin(1.7 * id);
        const Vec3 x(i * dx + wobble, j * dx - 0.5 * wobble, nz > 1 ? k * dx + 0.3 * wobble : 0.0);
        const ParticleKind kind = j == 0 ? ParticleKind::dummy : j == 1 ? ParticleKind::wall : ParticleKind::material;
        const Vec3 normal = kind == ParticleKind::wall ? Vec3(Vec3::UnitY()) : Vec3(Vec3::Zero());
        c.push_back(x, id, Vec3(0.1 * id, -0.2 * id, 0.0), 3.0 * id, kind == ParticleKind::material ? 0 : -1, kind,
                    kind == ParticleKind::material ? -1 : 0, normal, 1.0 + 0.001 * id);
      }
    }
  }
  return c;
}

// The particles of `all` that rank r of n keeps to start with: every n-th (so that each rank
// starts with particles everywhere, as on a rank-0 read).
inline ParticleCloud everyNth(const ParticleCloud& all, int r, int n) {
  ParticleCloud c;
  c.properties = all.properties;
  for (std::size_t i = static_cast<std::size_t>(r); i < all.size(); i += static_cast<std::size_t>(n)) {
    c.push_back(all.positions[i], all.origId[i], all.U[i], all.p[i], all.material[i],
                static_cast<ParticleKind>(all.kind[i]), all.patch[i], all.normal[i], all.mass[i]);
  }
  return c;
}

// Every field of particle i of `c` is particle a's of `ref` (its position moved by `shift`).
inline void expectSameParticle(const ParticleCloud& c, std::size_t i, const ParticleCloud& ref, std::size_t a,
                               const Vec3& shift = Vec3::Zero()) {
  EXPECT_EQ(c.origId[i], ref.origId[a]);
  EXPECT_EQ(c.positions[i], ref.positions[a] + shift);
  EXPECT_EQ(c.U[i], ref.U[a]);
  EXPECT_EQ(c.p[i], ref.p[a]);
  EXPECT_EQ(c.material[i], ref.material[a]);
  EXPECT_EQ(c.kind[i], ref.kind[a]);
  EXPECT_EQ(c.patch[i], ref.patch[a]);
  EXPECT_EQ(c.normal[i], ref.normal[a]);
  EXPECT_EQ(c.mass[i], ref.mass[a]);
}

// Sum of a count over the ranks, as a size.
inline std::size_t totalOverRanks(std::size_t n) { return sumOverRanks(n); }

}  // namespace isph::test
