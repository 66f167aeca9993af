// A wall thinner than the kernel's support: a plate two spacings thick (dx = 0.01 m, support
// radius 2.6 dx) with a column of sand at 1000 Pa against its front face (normal −x) and
// nothing behind its back face (normal +x). The back face's wall particles lie within the
// support of the sand through the plate; they must take neither its pressure
// (updateWallPressure) nor give it friction (WallFriction), and the sand's friction normal
// must be the front face's. Without the side test (facesMaterial) the back face read the
// sand's 1000 Pa, and the barrier tutorial's 20 mm barrier carried 35-85 N on its back face
// at 10.8 mm (2026-12-02: the barrier README's history at 55b7e73).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "isph/walls/WallBoundaryPressure.hpp"
#include "isph/walls/WallFriction.hpp"
#include "MaterialTableForTest.hpp"
#include "isph/materials/MaterialTable.hpp"

namespace {

using namespace isph;
constexpr double dx = 0.01;

struct Plate {
  ParticleSystem ps;
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  std::unique_ptr<MaterialTable> materials;

  Plate() {
    materials = test::materialTable("WallBoundaryPressureTest", "sand { model rigidPlastic; rho 1500; phi 30; }", {"sand"});
    ParticleCloud& c = ps.cloud;
    c.properties.materials = {"sand"};
    c.properties.patches = {{"plate", 25.0}};
    c.properties.spacing = dx;
    for (int j = 0; j < 10; ++j) {
      const double y = (j + 0.5) * dx;
      c.push_back(Vec3(0, y, 0), 100 + j, Vec3::Zero(), 0.0, -1, ParticleKind::wall, 0, Vec3(-1, 0, 0), 0);
      c.push_back(Vec3(2 * dx, y, 0), 200 + j, Vec3::Zero(), 0.0, -1, ParticleKind::wall, 0, Vec3(1, 0, 0), 0);
      c.push_back(Vec3(dx, y, 0), 300 + j, Vec3::Zero(), 0.0, -1, ParticleKind::dummy, 0, Vec3::Zero(), 0);
      for (int i = 0; i < 3; ++i) {
        c.push_back(Vec3(-(i + 0.5) * dx, y, 0), 10 * j + i, Vec3(0, -0.1, 0), 1000.0, 0, ParticleKind::material,
                    -1, Vec3::Zero(), 1500 * dx * dx);
      }
    }
    initialiseParticleSystem(ps, *materials, *kernel);
    ps.neighbours.build(ps.cloud.positions, *kernel);
    ps.frictionWall.assign(ps.size(), 1);  // as the solver sets it: the plate has friction
    ps.wallPullLimit.assign(ps.size(), 0.0);
    ps.wallTangentialGradient.assign(ps.nMaterial, Vec3::Zero());
  }
};

TEST(WallBoundaryPressure, AThinWallsBackFaceTakesNoPressureFromTheMaterialInFront) {
  Plate plate;
  ParticleSystem& ps = plate.ps;
  const std::vector<Vec3> ustar(ps.size(), Vec3::Zero());  // at rest, no gravity: p_b(a) = p_a
  updateWallPressure(ps, ustar, Vec3::Zero(), 1e-3);
  int front = 0, back = 0;
  for (std::size_t b = ps.wallBegin(); b < ps.dummyBegin(); ++b) {
    const bool isFront = ps.cloud.normal[b].x() < 0;
    if (isFront) {
      EXPECT_NEAR(ps.cloud.p[b], 1000.0, 1e-9) << "front face particle " << b;
      ++front;
    } else {
      EXPECT_EQ(ps.cloud.p[b], 0.0) << "back face particle " << b << ": the sand is behind it";
      ++back;
    }
  }
  EXPECT_EQ(front, 10);
  EXPECT_EQ(back, 10);
}

TEST(WallBoundaryPressure, AThinWallsBackFaceGivesNoFriction) {
  Plate plate;
  ParticleSystem& ps = plate.ps;
  const std::vector<Vec3> ustar(ps.size(), Vec3::Zero());
  updateWallPressure(ps, ustar, Vec3::Zero(), 1e-3);
  // Give the back face a pressure of its own, as if sand stood behind it: the sand in front
  // must still see only the front face's friction and normal.
  for (std::size_t b = ps.wallBegin(); b < ps.dummyBegin(); ++b) {
    if (ps.cloud.normal[b].x() > 0) ps.cloud.p[b] = 5000.0;
  }
  WallFriction friction(ps, *plate.materials, Vec3(0, -9.81, 0), 1e-5);
  ASSERT_TRUE(friction.active());
  friction.update(ps);
  // Each front-face particle shares tan δ σ_w A_w (σ_w = its 1000 Pa; the half layer is zero
  // here, gravity runs along the wall) over the material in front of it, so the capacities
  // sum to 10 × tan 25° × 1000 Pa × dx exactly; the back face's 5000 Pa would add 5 times that.
  double total = 0;
  int rubbing = 0;
  for (std::size_t a = 0; a < ps.nMaterial; ++a) {
    if (friction.capacity(a) <= 0) continue;
    ++rubbing;
    total += friction.capacity(a);
    EXPECT_NEAR(friction.normal(a).x(), -1.0, 1e-12) << "material particle " << a << ": the front face's normal";
  }
  EXPECT_GT(rubbing, 0);
  const double expected = 10 * std::tan(25.0 * std::numbers::pi / 180) * 1000.0 * dx;
  EXPECT_NEAR(total, expected, 1e-9 * expected) << "no capacity from the back face";
}

}  // namespace
