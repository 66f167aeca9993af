// The walls' share of the Coulomb friction (WallFriction::wallTraction), 2D, Wendland C2 with
// h = 1.3 dx: two rows of rock (dx = 0.01 m) on a bed of 20 wall particles, the left 10 of
// a friction patch (δ = 30°), the right 10 of a free-slip patch. Given the friction force f_a
// on each material particle, the traction on the walls must be its reaction, exactly:
// Σ_w A_w t_w = −Σ_a f_a (Newton's third law, to rounding), with none on the free-slip patch
// and none on the dummies; the explicit friction's forces are m_a Δu_a/dt.
#include <gtest/gtest.h>

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

// `rows` rows of rock on the bed. Bed(): two sliding rows at 100 Pa, the walls at 500 Pa;
// Bed(n, lithostatic): n rows at rest with the pressure ρ g ((n − ½) dx − y), the walls at 0.
struct Bed {
  ParticleSystem ps;
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  std::unique_ptr<MaterialTable> materials;
  static constexpr double rho = 2000, g = 9.81;

  explicit Bed(int rows = 2, bool lithostatic = false) {
    materials = test::materialTable("WallFrictionTest", "rock { model rigidPlastic; rho 2000; phi 40; }", {"rock"});
    ParticleCloud& c = ps.cloud;
    c.properties.materials = {"rock"};
    c.properties.patches = {{"rough", 30.0}, {"smooth", 0.0}};
    c.properties.spacing = dx;
    const double wallP = lithostatic ? 0.0 : 500.0;
    for (int i = 0; i < 20; ++i) {
      const double x = (i + 0.5) * dx;
      const label patch = i < 10 ? 0 : 1;
      c.push_back(Vec3(x, 0, 0), 1000 + i, Vec3::Zero(), wallP, -1, ParticleKind::wall, patch, Vec3(0, 1, 0), 0);
      c.push_back(Vec3(x, -dx, 0), 2000 + i, Vec3::Zero(), wallP, -1, ParticleKind::dummy, patch, Vec3::Zero(), 0);
      for (int j = 0; j < rows; ++j) {
        const double y = (j + 0.5) * dx;
        const double p = lithostatic ? rho * g * ((rows - 0.5) * dx - y) : 100.0;
        c.push_back(Vec3(x, y, 0), rows * i + j, lithostatic ? Vec3::Zero() : Vec3(1, 0, 0), p, 0,
                    ParticleKind::material, -1, Vec3::Zero(), rho * dx * dx);
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

// The capacity's wall stress. Six rows of rock (dx = 0.01 m, ρ = 2000) at rest on the same
// bed, with their lithostatic pressure ρ g (5.5 dx − y) (p = 0 at the top row's centres): both
// ways of taking σ_w give Σ_a F_a = tan δ × the weight of the rock over the rough patch
// (σ_w = ρ g 5.5 dx at the wall line, plus the half layer: 6 rows). Then the bottom three
// rows rattle: every other particle's u* points 0.05 m/s into the bed, the others' 0.05 m/s
// out of it (zero mean; dt = 1 ms). The walls' pressure answers the approaches with
// ρ u*·n/dt r_n and the departures only down to −p_a (WallBoundaryPressure.hpp), so the
// wall-pressure capacity rises above the weight (1.27 times); the hydrostatic one does not move.
struct Layer : Bed {
  static constexpr int rows = 6;

  Layer() : Bed(rows, true) {
    ps.frictionWall.assign(ps.size(), 0);
    for (std::size_t b = ps.wallBegin(); b < ps.size(); ++b) ps.frictionWall[b] = ps.cloud.patch[b] == 0;
    ps.wallPullLimit.assign(ps.cloud.p.begin(), ps.cloud.p.begin() + static_cast<long>(ps.nMaterial));
    ps.wallTangentialGradient.assign(ps.nMaterial, Vec3::Zero());  // flat and at rest
  }

  // Σ_a F_a after the walls take their pressure from u*.
  double capacity(FrictionNormal normal, const std::vector<Vec3>& ustar, double dt) {
    updateWallPressure(ps, ustar, Vec3(0, -g, 0), dt);
    WallFriction friction(ps, *materials, Vec3(0, -g, 0), 1e-5, normal);
    friction.update(ps);
    double sum = 0;
    for (std::size_t a = 0; a < ps.nMaterial; ++a) sum += friction.capacity(a);
    return sum;
  }
};

TEST(WallFriction, CapacityIsTanDeltaTimesTheWeightAndTheHydrostaticOneIgnoresRattling) {
  Layer l;
  const double dt = 1e-3;
  const double expected = std::tan(30.0 * std::numbers::pi / 180.0) * 10 * Layer::rows * Layer::rho * dx * dx * Layer::g;
  std::vector<Vec3> resting(l.ps.size(), Vec3::Zero());
  for (std::size_t a = 0; a < l.ps.nMaterial; ++a) resting[a] = dt * Vec3(0, -Layer::g, 0);  // u* of a layer at rest
  // The wall line is 0.5 dx below the bottom row: the lattice's kernel sums are exact there.
  EXPECT_NEAR(l.capacity(FrictionNormal::wallPressure, resting, dt) / expected, 1.0, 0.01);
  EXPECT_NEAR(l.capacity(FrictionNormal::hydrostatic, resting, dt) / expected, 1.0, 0.01);

  std::vector<Vec3> rattling = resting;
  for (std::size_t a = 0; a < l.ps.nMaterial; ++a) {
    if (l.ps.cloud.positions[a].y() < 3 * dx) rattling[a].y() += (l.ps.cloud.origId[a] % 2 == 0 ? -0.05 : 0.05);
  }
  const double wallPressure = l.capacity(FrictionNormal::wallPressure, rattling, dt) / expected;
  const double hydrostatic = l.capacity(FrictionNormal::hydrostatic, rattling, dt) / expected;
  std::printf("capacity over tan(delta) x weight, rattling: wall pressure %.3f, hydrostatic %.3f\n", wallPressure,
              hydrostatic);
  EXPECT_GT(wallPressure, 1.2) << "the rattle should raise the walls' pressure (1.27 measured; else this test shows nothing)";
  EXPECT_NEAR(hydrostatic, 1.0, 0.01);
}

// Sand lying on a rough bed in one row at rest (p = 0: all of it free surface), the walls'
// pressure from u* = dt g, 40 wall particles: a row of 20, the same row with every other
// particle gone, one particle in every fourth place, and a lone particle. Each particle should
// carry tan δ times its own weight (σ_w = ρ g dx/2 at the wall line plus the half layer),
// however sparse the row (issue 55's goal: a wall carries at most tan δ times the normal stress
// of the layer's weight). Below goal, so DISABLED_: each wall particle within reach of any
// material gives the capacity of a full row (σ_w is a Shepard mean), so the sums are 1.20,
// 2.30, 4.20 and 5.00 times that (the row's ends; the gaps; a lone particle gathers five wall
// particles' worth and sticks on a 45° wall of friction 25°: the film of issue 55). Counting the
// part of each wall particle's area the material covers (doc/notes/thinLayers-coverage.patch)
// gives 1.0000 in all four, but moves the thick layers' ends (doc/notes/thinLayers.md, "Why a
// thin layer is held"). The tolerance 1 % is the lattice's kernel-sum error at the row's ends.
struct SparseRow {
  ParticleSystem ps;
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  std::unique_ptr<MaterialTable> materials;
  static constexpr double rho = 2000, g = 9.81;

  explicit SparseRow(const std::vector<int>& sites) {
    materials = test::materialTable("WallFrictionTest", "rock { model rigidPlastic; rho 2000; phi 40; }", {"rock"});
    ParticleCloud& c = ps.cloud;
    c.properties.materials = {"rock"};
    c.properties.patches = {{"rough", 30.0}};
    c.properties.spacing = dx;
    for (int i = 0; i < 40; ++i) {
      const double x = (i + 0.5) * dx;
      c.push_back(Vec3(x, 0, 0), 1000 + i, Vec3::Zero(), 0.0, -1, ParticleKind::wall, 0, Vec3(0, 1, 0), 0);
      c.push_back(Vec3(x, -dx, 0), 2000 + i, Vec3::Zero(), 0.0, -1, ParticleKind::dummy, 0, Vec3::Zero(), 0);
    }
    for (int i : sites) {
      c.push_back(Vec3((i + 0.5) * dx, 0.5 * dx, 0), i, Vec3::Zero(), 0.0, 0, ParticleKind::material, -1,
                  Vec3::Zero(), rho * dx * dx);
    }
    initialiseParticleSystem(ps, *materials, *kernel);
    ps.neighbours.build(ps.cloud.positions, *kernel);
    ps.frictionWall.assign(ps.size(), 1);
    ps.wallPullLimit.assign(ps.nMaterial, 0.0);
    ps.wallTangentialGradient.assign(ps.nMaterial, Vec3::Zero());
  }

  // Σ_a F_a over tan δ × the particles' weight.
  double capacityOverWeight() {
    const double dt = 1e-3;
    std::vector<Vec3> resting(ps.size(), Vec3::Zero());
    for (std::size_t a = 0; a < ps.nMaterial; ++a) resting[a] = dt * Vec3(0, -g, 0);
    updateWallPressure(ps, resting, Vec3(0, -g, 0), dt);
    WallFriction friction(ps, *materials, Vec3(0, -g, 0), 1e-5);
    friction.update(ps);
    double sum = 0;
    for (std::size_t a = 0; a < ps.nMaterial; ++a) sum += friction.capacity(a);
    return sum / (std::tan(30.0 * std::numbers::pi / 180.0) * static_cast<double>(ps.nMaterial) * rho * dx * dx * g);
  }
};

TEST(WallFriction, DISABLED_EachParticleOfASparseRowCarriesItsOwnWeightsFriction) {
  std::vector<int> full, everyOther, everyFourth;
  for (int i = 10; i < 30; ++i) {
    full.push_back(i);
    if (i % 2 == 0) everyOther.push_back(i);
    if (i % 4 == 0) everyFourth.push_back(i);
  }
  const std::pair<const char*, std::vector<int>> rows[] = {
      {"a full row", full}, {"every other site", everyOther}, {"every fourth site", everyFourth}, {"a lone particle", {20}}};
  for (const auto& [name, sites] : rows) {
    SparseRow r(sites);
    const double ratio = r.capacityOverWeight();
    std::printf("%s: capacity over tan(delta) x weight %.4f\n", name, ratio);
    EXPECT_NEAR(ratio, 1.0, 0.01) << name;
  }
}

}  // namespace
