// The deviatoric stress carried to the wall particles by a Shepard average over the material.
#include "postProcessing/forces/WallStress.hpp"

#include <gtest/gtest.h>

#include "../PostProcessingTestHelpers.hpp"
#include "sph/kernels/WendlandC2.hpp"

namespace isph {
namespace {

// A bed of 20 wall particles (dx = 0.1) under 4 rows of material, one dummy row below, and a
// wall particle far from all material.
ParticleCloud bedUnderMaterial() {
  const double dx = 0.1;
  ParticleCloud c = pptest::flatBed(20, dx, 0.0);
  for (int row = 2; row <= 4; ++row) {
    for (int i = 0; i < 20; ++i) {
      c.push_back(Vec3((i + 0.5) * dx, row * dx, 0), 1000 + 20 * row + i, Vec3::Zero(), 0, 0, ParticleKind::material,
                  -1, Vec3::Zero(), 1);
    }
  }
  c.push_back(Vec3(10, 0, 0), 5000, Vec3::Zero(), 0, -1, ParticleKind::wall, 0, Vec3(0, 1, 0), 0);
  return c;
}

TEST(WallStress, UniformStressIsCarriedExactly) {
  const ParticleCloud c = bedUnderMaterial();
  SymmTensor t;
  t << 1, 2, 0, -3, 0, 0.5;
  std::vector<SymmTensor> tau(c.size(), SymmTensor::Zero());
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] == static_cast<label>(ParticleKind::material)) tau[i] = t;
  }
  const WendlandC2 kernel(1.3 * 0.1, 2);
  NeighbourList nl;
  nl.build(c.positions, kernel);
  const auto wallTau = wallDeviatoricStress(c, tau, nl);
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] != static_cast<label>(ParticleKind::wall)) {
      EXPECT_EQ(wallTau[i], SymmTensor::Zero()) << "particle " << i << " is not a wall particle";
    } else if (c.positions[i].x() > 5) {
      EXPECT_EQ(wallTau[i], SymmTensor::Zero()) << "a wall particle with no material neighbour";
    } else {
      EXPECT_LT((wallTau[i] - t).norm(), 1e-12 * t.norm()) << "wall particle " << i;
    }
  }
}

TEST(WallStress, LinearStressAlongTheWallIsExactAwayFromTheEnds) {
  // τ_xy = 10 x: the lattice is symmetric about each interior wall particle, so the Shepard
  // average is 10 x_w there.
  const ParticleCloud c = bedUnderMaterial();
  std::vector<SymmTensor> tau(c.size(), SymmTensor::Zero());
  for (std::size_t i = 0; i < c.size(); ++i) tau[i][1] = 10 * c.positions[i].x();
  const WendlandC2 kernel(1.3 * 0.1, 2);
  NeighbourList nl;
  nl.build(c.positions, kernel);
  std::vector<char> selected(c.size(), 1);
  const auto wallTau = wallDeviatoricStress(c, tau, nl, &selected);
  int checked = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double x = c.positions[i].x();
    if (c.kind[i] != static_cast<label>(ParticleKind::wall) || x < 0.3 || x > 1.7) continue;
    EXPECT_NEAR(wallTau[i][1], 10 * x, 1e-12) << "wall particle at x = " << x;
    ++checked;
  }
  EXPECT_EQ(checked, 14);
}

TEST(WallStress, DotSymmUsesOpenFoamComponentOrder) {
  SymmTensor t;
  t << 1, 2, 3, 4, 5, 6;  // xx xy xz yy yz zz
  EXPECT_EQ(dotSymm(t, Vec3(1, 0, 0)), Vec3(1, 2, 3));
  EXPECT_EQ(dotSymm(t, Vec3(0, 1, 0)), Vec3(2, 4, 5));
  EXPECT_EQ(dotSymm(t, Vec3(0, 0, 1)), Vec3(3, 5, 6));
}

}  // namespace
}  // namespace isph
