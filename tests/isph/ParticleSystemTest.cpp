// The particle system as the solver sets it up (ParticleSystem.hpp), 2D, Wendland C2 with
// h = 1.3 dx, dx = 0.01 m, on a hand-built scene: a 6 × 6 lattice block (centres at
// (i + ½) dx, (j + ½) dx) of sand (ρ 2000, its four lower rows) under water (ρ 1000, its two upper
// rows; its particles carry half a site's mass, a volume of dx²/2) on a flat bed: a row of 6 wall
// particles on y = 0 (the left three of patch roughBed, wall friction angle 20°, the right three
// of smoothBed, 0°) and two rows of dummy particles below at y = −dx, −2dx, every particle pushed
// into the cloud in a shuffled order (fixed seed).
// What is asserted:
//  - initialiseParticleSystem: the cloud ordered material | wall | dummy, each kind in its input
//    order; ρ the material's for material particles and, for walls and dummies, the materials'
//    bulk density Σm / Σ(m/ρ); the volume m/ρ of a material particle (a hexagonal site's area
//    when its mass is that of one) and dx² for walls and dummies; the lattice sum that of an
//    interior particle of a full lattice block (square and hexagonal); each dummy's wall the one
//    straight above it, and the smaller origId of two equally near; FatalError for a cloud
//    without material, a spacing that is not positive, a dummy with no wall in reach;
//  - markFrictionWalls: the walls of the patch with a friction angle and the dummies behind them
//    (by their wall's patch, not their own label), no material particle;
//  - reorderMaterialParticles: order[new] = old over the material only, every field of the
//    cloud and ρ, V moved with it (checked by origId), walls and dummies untouched, the material
//    then sorted cell by cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numeric>
#include <random>
#include <vector>

#include "LatticeBlockForTest.hpp"
#include "MaterialTableForTest.hpp"
#include "core/Error.hpp"
#include "isph/ParticleSystem.hpp"

namespace {

using namespace isph;

constexpr double dx = 0.01, rhoSand = 2000, rhoWater = 1000;
constexpr int n = 6, sandRows = 4, dummyLayers = 2;
constexpr label nMaterial = n * n, nWall = n, nDummy = dummyLayers * n;

label kindOf(label id) {
  return id < nMaterial           ? label(ParticleKind::material)
         : id < nMaterial + nWall ? label(ParticleKind::wall)
                                  : label(ParticleKind::dummy);
}

// The particle of origId `id` (material j n + i, wall n² + i, dummy n² + n + (l − 1) n + i), with
// a velocity and a pressure of its own so that a permutation can be followed field by field.
struct Particle {
  Vec3 x, U, normal;
  double p, mass;
  label material, patch;
};

Particle particle(label id) {
  Particle q;
  q.U = Vec3(0.1 * id, -0.2 * id, 0);
  q.p = 10.0 * id + 1;
  q.normal = Vec3::Zero();
  q.material = -1;
  q.patch = -1;
  q.mass = 0;
  if (id < nMaterial) {
    const int i = id % n, j = id / n;
    q.x = Vec3((i + 0.5) * dx, (j + 0.5) * dx, 0);
    q.material = j < sandRows ? 0 : 1;
    q.mass = j < sandRows ? rhoSand * dx * dx : rhoWater * dx * dx / 2;
  } else if (id < nMaterial + nWall) {
    const int i = id - nMaterial;
    q.x = Vec3((i + 0.5) * dx, 0, 0);
    q.patch = i < n / 2 ? 0 : 1;  // roughBed | smoothBed
    q.normal = Vec3(0, 1, 0);
  } else {
    const int k = id - nMaterial - nWall, i = k % n, l = k / n + 1;
    q.x = Vec3((i + 0.5) * dx, -l * dx, 0);
    q.patch = i < n / 2 ? 1 : 0;  // the other patch than its wall's: only the wall's may count
  }
  return q;
}

// The scene's origIds in the order they are pushed (shuffled, fixed seed).
std::vector<label> inputOrder() {
  std::vector<label> ids(static_cast<std::size_t>(nMaterial + nWall + nDummy));
  std::iota(ids.begin(), ids.end(), 0);
  std::shuffle(ids.begin(), ids.end(), std::mt19937(7));
  return ids;
}

struct Scene {
  std::unique_ptr<Kernel> kernel = makeKernel("WendlandC2", 1.3 * dx, 2);
  std::unique_ptr<MaterialTable> materials =
      test::materialTable("ParticleSystemTest",
                          "sand { model rigidPlastic; rho 2000; phi 30; } water { model newtonian; "
                          "rho 1000; nu 1e-6; }",
                          {"sand", "water"});
  ParticleSystem ps;

  Scene() {
    ParticleCloud& c = ps.cloud;
    c.name = "landslide";
    c.properties.materials = {"sand", "water"};
    c.properties.patches = {{"roughBed", 20.0}, {"smoothBed", 0.0}};
    c.properties.spacing = dx;
    for (const label id : inputOrder()) push(id);
  }
  void push(label id) {
    const Particle q = particle(id);
    ps.cloud.push_back(q.x, id, q.U, q.p, q.material, ParticleKind(kindOf(id)), q.patch, q.normal,
                       q.mass);
  }
};

std::string fatalMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const FatalError& e) {
    return e.what();
  }
  return "(no FatalError)";
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

TEST(ParticleSystem, TheCloudIsOrderedMaterialThenWallThenDummyEachInItsInputOrder) {
  Scene s;
  initialiseParticleSystem(s.ps, *s.materials, *s.kernel);
  const auto& c = s.ps.cloud;
  EXPECT_EQ(s.ps.nMaterial, std::size_t(nMaterial));
  EXPECT_EQ(s.ps.nWall, std::size_t(nWall));
  EXPECT_EQ(s.ps.nDummy, std::size_t(nDummy));
  EXPECT_EQ(s.ps.dimension, 2);
  EXPECT_EQ(s.ps.dx, dx);
  // The input order of each kind: the shuffled ids filtered by kind.
  std::vector<label> expected;
  for (const label kind : {0, 1, 2}) {
    for (const label id : inputOrder())
      if (kindOf(id) == kind) expected.push_back(id);
  }
  ASSERT_EQ(c.origId, expected);
  for (std::size_t a = 0; a < s.ps.size(); ++a) {
    const label id = c.origId[a];
    const Particle q = particle(id);
    EXPECT_EQ(c.kind[a], kindOf(id)) << "particle " << a;
    EXPECT_EQ(c.positions[a], q.x) << "origId " << id << ": the fields move with the particle";
    EXPECT_EQ(c.U[a], q.U) << "origId " << id;
    EXPECT_EQ(c.p[a], q.p) << "origId " << id;
    EXPECT_EQ(c.material[a], q.material) << "origId " << id;
    EXPECT_EQ(c.patch[a], q.patch) << "origId " << id;
    EXPECT_EQ(c.mass[a], q.mass) << "origId " << id;
  }
  for (std::size_t a = 0; a < s.ps.size(); ++a) {
    EXPECT_EQ(s.ps.isMaterial(a), c.kind[a] == label(ParticleKind::material));
    EXPECT_EQ(s.ps.isWall(a), c.kind[a] == label(ParticleKind::wall));
    EXPECT_EQ(s.ps.isDummy(a), c.kind[a] == label(ParticleKind::dummy));
  }
}

// 24 sand particles of 2000 dx² kg/m and 12 of water of 1000 dx²/2: Σm / Σ(m/ρ) =
// (48000 + 6000) / (24 + 6) = 1800 kg/m³, the materials' bulk density (the mean of ρ over the
// particles would be 1666.7, the mass-weighted Σ m ρ / Σ m 1888.9). Exact up to rounding (1e-14).
TEST(ParticleSystem, MaterialsTakeTheirDensityAndWallsTheBulkDensityOfTheMaterials) {
  Scene s;
  initialiseParticleSystem(s.ps, *s.materials, *s.kernel);
  const auto& c = s.ps.cloud;
  EXPECT_NEAR(s.ps.wallRho, 1800, 1e-14 * 1800);
  ASSERT_EQ(s.ps.rho.size(), s.ps.size());
  ASSERT_EQ(s.ps.volume.size(), s.ps.size());
  for (std::size_t a = 0; a < s.ps.size(); ++a) {
    if (s.ps.isMaterial(a)) {
      const bool sand = c.material[a] == 0;
      EXPECT_EQ(s.ps.rho[a], sand ? rhoSand : rhoWater) << "origId " << c.origId[a];
      EXPECT_NEAR(s.ps.volume[a], sand ? dx * dx : dx * dx / 2, 1e-15 * dx * dx)
          << "m/ρ, origId " << c.origId[a];
    } else {
      EXPECT_EQ(s.ps.rho[a], s.ps.wallRho) << "origId " << c.origId[a];
      EXPECT_EQ(s.ps.volume[a], dx * dx) << "a wall site's area, origId " << c.origId[a];
    }
  }
}

// Σ_b V_b W_ab over a full lattice, self included (V W(0)), against the same sum taken through
// the neighbour list at the centre of a 14 × 14 lattice block, whose support (2.6 dx) is whole.
// Measured 1.01047 on the square lattice (the kernel's integral, 1, to 1 %); equal up to rounding
// (summation order): 1e-14.
TEST(ParticleSystem, TheLatticeSumIsThatOfAnInteriorParticleOfASquareLattice) {
  Scene s;
  initialiseParticleSystem(s.ps, *s.materials, *s.kernel);
  constexpr int m = 14;
  const ParticleSystem block = test::latticeBlock(*s.kernel, m, dx);
  const std::size_t a = (m / 2) * m + m / 2;
  ASSERT_TRUE(test::inInterior(a, m));
  double sum = dx * dx * s.kernel->W(0);
  for (long k = block.neighbours.start[a]; k < block.neighbours.start[a + 1]; ++k)
    sum +=
        block
            .volume[static_cast<std::size_t>(block.neighbours.index[static_cast<std::size_t>(k)])] *
        block.neighbours.W[static_cast<std::size_t>(k)];
  std::printf("lattice sum: square %.9g, interior particle %.9g\n", s.ps.latticeSum, sum);
  EXPECT_NEAR(s.ps.latticeSum, sum, 1e-14);
  EXPECT_NEAR(s.ps.latticeSum, 1.0, 0.02) << "the kernel's integral";
}

// A hexagonal lattice (rows dy = √3/2 dx apart, every other row shifted by dx/2): the particles'
// masses scaled by √3/2, a hexagonal site's, so that the sand's volume is √3/2 dx² (the water's
// half that; the walls keep dx²); the lattice sum is that of the centre of a 14 × 16 hexagonal
// block of sites √3/2 dx², through its neighbour list. Measured 1.00671 (square: 1.01047); equal
// up to rounding, 1e-14.
TEST(ParticleSystem, TheLatticeSumAndVolumesFollowAHexagonalLattice) {
  Scene s;
  const double site = std::sqrt(3.0) / 2 * dx * dx;
  s.ps.cloud.properties.lattice = "hexagonal";
  for (std::size_t a = 0; a < s.ps.size(); ++a) s.ps.cloud.mass[a] *= std::sqrt(3.0) / 2;
  initialiseParticleSystem(s.ps, *s.materials, *s.kernel);
  for (std::size_t a = 0; a < s.ps.size(); ++a) {
    const double expected = !s.ps.isMaterial(a)           ? dx * dx
                            : s.ps.cloud.material[a] == 0 ? site
                                                          : site / 2;
    EXPECT_NEAR(s.ps.volume[a], expected, 1e-15 * dx * dx) << "particle " << a;
  }

  std::vector<Vec3> x;
  constexpr int nx = 14, ny = 16;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      x.emplace_back((i + 0.5 * (j & 1)) * dx, j * std::sqrt(3.0) / 2 * dx, 0);
  NeighbourList nl;
  nl.build(x, *s.kernel);
  const std::size_t a =
      (ny / 2) * nx + nx / 2;  // ≥ 6 rows and 6 columns from every edge (> 2.6 dx)
  double sum = site * s.kernel->W(0);
  for (long k = nl.start[a]; k < nl.start[a + 1]; ++k)
    sum += site * nl.W[static_cast<std::size_t>(k)];
  std::printf("lattice sum: hexagonal %.9g, interior particle %.9g\n", s.ps.latticeSum, sum);
  EXPECT_NEAR(s.ps.latticeSum, sum, 1e-14);
}

TEST(ParticleSystem, EachDummyExtendsTheWallParticleStraightAboveIt) {
  Scene s;
  initialiseParticleSystem(s.ps, *s.materials, *s.kernel);
  const auto& c = s.ps.cloud;
  ASSERT_EQ(s.ps.parentWall.size(), s.ps.size());
  for (std::size_t a = 0; a < s.ps.dummyBegin(); ++a)
    EXPECT_EQ(s.ps.parentWall[a], -1) << "particle " << a;
  for (std::size_t d = s.ps.dummyBegin(); d < s.ps.size(); ++d) {
    const int w = s.ps.parentWall[d];
    ASSERT_TRUE(w >= 0 && s.ps.isWall(static_cast<std::size_t>(w)))
        << "dummy origId " << c.origId[d];
    const label column = (c.origId[d] - nMaterial - nWall) % n;
    EXPECT_EQ(c.origId[static_cast<std::size_t>(w)], nMaterial + column)
        << "dummy origId " << c.origId[d];
  }
}

// A dummy at (0, −dx) between wall particles at x = −dx/2 (origId 39) and +dx/2 (origId 38),
// equally near to the last bit, pushed in either order: it extends origId 38 in both.
TEST(ParticleSystem, OfTwoEquallyNearWallsADummyTakesTheSmallerOrigId) {
  for (const bool reversed : {false, true}) {
    Scene s;
    ParticleCloud& c = s.ps.cloud;
    c.resize(0);
    c.push_back(Vec3(0.5 * dx, 0.5 * dx, 0), 0, Vec3::Zero(), 0, 0, ParticleKind::material, -1,
                Vec3::Zero(), rhoSand * dx * dx);
    c.push_back(Vec3(0, -dx, 0), 100, Vec3::Zero(), 0, -1, ParticleKind::dummy, -1, Vec3::Zero(),
                0);
    const auto wall = [&](label id, double x) {
      c.push_back(Vec3(x, 0, 0), id, Vec3::Zero(), 0, -1, ParticleKind::wall, 0, Vec3(0, 1, 0), 0);
    };
    if (reversed) {
      wall(38, 0.5 * dx);
      wall(39, -0.5 * dx);
    } else {
      wall(39, -0.5 * dx);
      wall(38, 0.5 * dx);
    }
    initialiseParticleSystem(s.ps, *s.materials, *s.kernel);
    ASSERT_EQ(s.ps.nDummy, 1u);
    EXPECT_EQ(c.origId[static_cast<std::size_t>(s.ps.parentWall[s.ps.dummyBegin()])], 38)
        << (reversed ? "walls pushed 38, 39" : "walls pushed 39, 38");
  }
}

TEST(ParticleSystem, ACloudWithoutMaterialIsAFatalErrorNamingIt) {
  Scene s;
  s.ps.cloud.resize(0);
  for (label id = nMaterial; id < nMaterial + nWall + nDummy; ++id) s.push(id);  // the bed alone
  const std::string m =
      fatalMessage([&] { initialiseParticleSystem(s.ps, *s.materials, *s.kernel); });
  EXPECT_TRUE(contains(m, "cloud 'landslide' has no material particles")) << m;
}

TEST(ParticleSystem, ASpacingThatIsNotPositiveIsAFatalError) {
  Scene s;
  s.ps.cloud.properties.spacing = 0;
  const std::string m =
      fatalMessage([&] { initialiseParticleSystem(s.ps, *s.materials, *s.kernel); });
  EXPECT_TRUE(contains(m, "cloud 'landslide'") && contains(m, "spacing")) << m;
}

// The dummies are looked for within twice the support, 5.2 dx: one 6 dx below the bed has none.
TEST(ParticleSystem, ADummyWithNoWallInReachIsAFatalError) {
  Scene s;
  s.ps.cloud.push_back(Vec3(0.5 * dx, -6 * dx, 0), 999, Vec3::Zero(), 0, -1, ParticleKind::dummy, 0,
                       Vec3::Zero(), 0);
  const std::string m =
      fatalMessage([&] { initialiseParticleSystem(s.ps, *s.materials, *s.kernel); });
  EXPECT_TRUE(contains(m, "dummy particle at (0.005 -0.06)") && contains(m, "no wall particle"))
      << m;
}

TEST(ParticleSystem, FrictionWallsAreThoseOfAPatchWithAFrictionAngleAndTheDummiesBehindThem) {
  Scene s;
  initialiseParticleSystem(s.ps, *s.materials, *s.kernel);
  markFrictionWalls(s.ps);
  const auto& c = s.ps.cloud;
  ASSERT_EQ(s.ps.frictionWall.size(), s.ps.size());
  int rough = 0;
  for (std::size_t a = 0; a < s.ps.size(); ++a) {
    const label id = c.origId[a];
    const int column = id < nMaterial + nWall ? id - nMaterial : (id - nMaterial - nWall) % n;
    const bool expected = !s.ps.isMaterial(a) && column < n / 2;  // under roughBed (20°)
    EXPECT_EQ(bool(s.ps.frictionWall[a]), expected) << "origId " << id;
    rough += s.ps.frictionWall[a];
  }
  EXPECT_EQ(rough, (1 + dummyLayers) * n / 2);
}

TEST(ParticleSystem, NoWallIsAFrictionWallWhenNoPatchHasAFrictionAngle) {
  Scene s;
  s.ps.cloud.properties.patches[0].frictionAngle = 0;
  initialiseParticleSystem(s.ps, *s.materials, *s.kernel);
  markFrictionWalls(s.ps);
  EXPECT_EQ(std::count(s.ps.frictionWall.begin(), s.ps.frictionWall.end(), 1), 0);
}

// The material, shuffled on input, reordered by cells of the support radius (2.6 dx).
TEST(ParticleSystem, ReorderingPermutesEveryFieldOfTheMaterialOnly) {
  Scene s;
  initialiseParticleSystem(s.ps, *s.materials, *s.kernel);
  markFrictionWalls(s.ps);
  const ParticleSystem before = s.ps;
  const double cell = s.kernel->supportRadius();
  const std::vector<int> order = reorderMaterialParticles(s.ps, cell);
  const auto& c = s.ps.cloud;
  const auto& b = before.cloud;

  ASSERT_EQ(order.size(), s.ps.nMaterial);
  std::vector<int> sorted(order);
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> identity(s.ps.nMaterial);
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(sorted, identity) << "a permutation of the material";
  EXPECT_NE(order, identity) << "the shuffled material is reordered";

  for (std::size_t i = 0; i < s.ps.nMaterial; ++i) {
    const auto o = static_cast<std::size_t>(order[i]);
    EXPECT_EQ(c.origId[i], b.origId[o]) << "order[new] = old, new " << i;
    const Particle q = particle(c.origId[i]);
    EXPECT_EQ(c.positions[i], q.x) << "origId " << c.origId[i];
    EXPECT_EQ(c.U[i], q.U) << "origId " << c.origId[i];
    EXPECT_EQ(c.p[i], q.p) << "origId " << c.origId[i];
    EXPECT_EQ(c.material[i], q.material) << "origId " << c.origId[i];
    EXPECT_EQ(c.mass[i], q.mass) << "origId " << c.origId[i];
    EXPECT_EQ(c.kind[i], label(ParticleKind::material)) << "origId " << c.origId[i];
    EXPECT_EQ(c.patch[i], -1) << "origId " << c.origId[i];
    EXPECT_EQ(c.normal[i], Vec3::Zero()) << "origId " << c.origId[i];
    EXPECT_EQ(s.ps.rho[i], before.rho[o]) << "origId " << c.origId[i];
    EXPECT_EQ(s.ps.rho[i], q.material == 0 ? rhoSand : rhoWater) << "origId " << c.origId[i];
    EXPECT_EQ(s.ps.volume[i], before.volume[o]) << "origId " << c.origId[i];
  }
  for (std::size_t a = s.ps.nMaterial; a < s.ps.size(); ++a) {
    EXPECT_EQ(c.origId[a], b.origId[a]) << "wall or dummy " << a << " stays";
    EXPECT_EQ(c.positions[a], b.positions[a]);
    EXPECT_EQ(c.U[a], b.U[a]);
    EXPECT_EQ(c.p[a], b.p[a]);
    EXPECT_EQ(c.patch[a], b.patch[a]);
    EXPECT_EQ(c.normal[a], b.normal[a]);
    EXPECT_EQ(s.ps.rho[a], before.rho[a]);
    EXPECT_EQ(s.ps.volume[a], before.volume[a]);
    EXPECT_EQ(s.ps.parentWall[a], before.parentWall[a]);
    EXPECT_EQ(s.ps.frictionWall[a], before.frictionWall[a]);
  }

  // Cell by cell, x fastest: cells of 2.6 dx from the material's lowest corner (2 × 2 of them).
  Vec3 lo = c.positions[0];
  for (std::size_t i = 0; i < s.ps.nMaterial; ++i) lo = lo.cwiseMin(c.positions[i]);
  const int cellsX = static_cast<int>(std::floor((n - 1) * dx / cell)) + 1;
  int last = -1;
  for (std::size_t i = 0; i < s.ps.nMaterial; ++i) {
    const Vec3 r = (c.positions[i] - lo) / cell;
    const int key =
        static_cast<int>(std::floor(r.y())) * cellsX + static_cast<int>(std::floor(r.x()));
    EXPECT_GE(key, last) << "new " << i << " (origId " << c.origId[i] << ") out of cell order";
    last = key;
  }
}

}  // namespace
