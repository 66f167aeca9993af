// The walls' share of the Coulomb friction (WallFriction::wallTraction), 2D, Wendland C2 with
// h = 1.3 dx: two rows of rock (dx = 0.01 m) on a bed of 20 wall particles, the left 10 of
// a friction patch (δ = 30°), the right 10 of a free-slip patch. Given the friction force f_a
// on each material particle, the traction on the walls must be its reaction, exactly:
// Σ_w A_w t_w = −Σ_a f_a (Newton's third law, to rounding), with none on the free-slip patch
// and none on the dummies; the explicit friction's forces are m_a Δu_a/dt.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "isph/WallFriction.hpp"
#include "MaterialTableForTest.hpp"
#include "isph/materials/MaterialTable.hpp"

namespace {

using namespace isph;
constexpr double dx = 0.01;

struct Bed {
  ParticleSystem ps;
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  std::unique_ptr<MaterialTable> materials;

  Bed() {
    materials = test::materialTable("WallFrictionTest", "rock { model rigidPlastic; rho 2000; phi 40; }", {"rock"});
    ParticleCloud& c = ps.cloud;
    c.properties.materials = {"rock"};
    c.properties.patches = {{"rough", 30.0}, {"smooth", 0.0}};
    c.properties.spacing = dx;
    for (int i = 0; i < 20; ++i) {
      const double x = (i + 0.5) * dx;
      const label patch = i < 10 ? 0 : 1;
      c.push_back(Vec3(x, 0, 0), 100 + i, Vec3::Zero(), 500.0, -1, ParticleKind::wall, patch, Vec3(0, 1, 0), 0);
      c.push_back(Vec3(x, -dx, 0), 200 + i, Vec3::Zero(), 500.0, -1, ParticleKind::dummy, patch, Vec3::Zero(), 0);
      for (int j = 0; j < 2; ++j) {
        c.push_back(Vec3(x, (j + 0.5) * dx, 0), 2 * i + j, Vec3(1, 0, 0), 100.0, 0, ParticleKind::material, -1,
                    Vec3::Zero(), 2000 * dx * dx);
      }
    }
    initialiseParticleSystem(ps, *materials, *kernel);
    ps.neighbours.build(ps.cloud.positions, *kernel);
  }
};

TEST(WallFriction, TheWallsTakeTheReactionToTheFrictionExactly) {
  Bed b;
  WallFriction friction(b.ps, *b.materials, Vec3(0, -9.81, 0), 1e-5);
  ASSERT_TRUE(friction.active());
  friction.update(b.ps);
  std::vector<Vec3> onMaterial(b.ps.nMaterial, Vec3::Zero());
  Vec3 sum = Vec3::Zero();
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    if (friction.capacity(a) <= 0) continue;
    onMaterial[a] = Vec3(-friction.capacity(a) * (1.0 + 0.01 * static_cast<double>(a)), 0, 0);  // uneven on purpose
    sum += onMaterial[a];
  }
  ASSERT_LT(sum.x(), 0.0) << "some material sits on the rough patch";
  const std::vector<Vec3> t = friction.wallTraction(b.ps, onMaterial);
  ASSERT_EQ(t.size(), b.ps.size());
  Vec3 onWalls = Vec3::Zero();
  for (std::size_t w = 0; w < b.ps.size(); ++w) {
    if (!b.ps.isWall(w)) {
      EXPECT_EQ(t[w], Vec3::Zero()) << "particle " << w << " is not a wall particle";
      continue;
    }
    if (b.ps.cloud.patch[w] == 1) {
      EXPECT_EQ(t[w], Vec3::Zero()) << "the free-slip patch takes no friction";
    }
    onWalls += dx * t[w];  // A_w = dx per metre
  }
  EXPECT_NEAR(onWalls.x(), -sum.x(), 1e-12 * std::abs(sum.x()));
  EXPECT_NEAR(onWalls.y(), 0.0, 1e-12 * std::abs(sum.x()));
}

TEST(WallFriction, ExplicitFrictionReportsTheForceItApplied) {
  Bed b;
  WallFriction friction(b.ps, *b.materials, Vec3(0, -9.81, 0), 1e-5);
  friction.update(b.ps);
  const double dt = 1e-4;
  std::vector<Vec3> u(b.ps.cloud.U.begin(), b.ps.cloud.U.begin() + static_cast<long>(b.ps.nMaterial));
  const std::vector<Vec3> before = u;
  std::vector<Vec3> applied;
  friction.applyExplicit(b.ps, dt, u, &applied);
  ASSERT_EQ(applied.size(), b.ps.nMaterial);
  int slowed = 0;
  for (std::size_t a = 0; a < b.ps.nMaterial; ++a) {
    const Vec3 expected = b.ps.cloud.mass[a] * (u[a] - before[a]) / dt;
    EXPECT_NEAR((applied[a] - expected).norm(), 0.0, 1e-9 * (1 + expected.norm())) << "particle " << a;
    if (applied[a].x() < 0) {
      ++slowed;
      EXPECT_NEAR(applied[a].x(), -friction.capacity(a), 1e-9 * friction.capacity(a)) << "slides at full capacity";
    }
  }
  EXPECT_GT(slowed, 0);
}

}  // namespace
