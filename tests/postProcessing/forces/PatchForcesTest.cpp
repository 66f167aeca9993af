// The force on a set of patches from wall pressure and deviatoric stress: values, signs,
// area, width, the normal/tangential split and the moment, on clouds where they are known.
#include "postProcessing/forces/PatchForces.hpp"

#include <gtest/gtest.h>

#include "../PostProcessingTestHelpers.hpp"
#include "core/Error.hpp"

namespace isph {
namespace {

constexpr double tol = 1e-12;

TEST(PatchForces, UniformPressureOnABedPushesItDown) {
  // 10 wall particles, dx = 0.1, p = 100 Pa: F = p × 1 m = 100 N/m along −y. The dummies
  // (p = 1000) and the material particles carry no surface and must not count.
  const ParticleCloud c = pptest::flatBed(10, 0.1, 100.0);
  const PatchForces f = patchForces({.cloud = c, .patches = {0}});
  EXPECT_EQ(f.nWall, 10);
  EXPECT_NEAR(f.pressure.x(), 0.0, tol);
  EXPECT_NEAR(f.pressure.y(), -100.0, tol);
  EXPECT_NEAR(f.deviatoric.norm(), 0.0, tol);
  EXPECT_NEAR(f.total.y(), -100.0, tol);
  EXPECT_NEAR(f.meanNormal.y(), 1.0, tol);
  EXPECT_NEAR(f.normal(f.total), 100.0, tol);  // positive: into the structure
  EXPECT_NEAR(f.tangential(f.total), 0.0, tol);
  // Moment about the origin: Σ x × f = Σ x_i (−10 N/m) = −10 × 5 m = −50 N m/m about z.
  EXPECT_NEAR(f.momentTotal.z(), -50.0, 1e-10);
  EXPECT_NEAR(f.momentPressure.z(), -50.0, 1e-10);
}

TEST(PatchForces, WidthScalesAndCofRShiftsTheMoment) {
  const ParticleCloud c = pptest::flatBed(10, 0.1, 100.0);
  const PatchForces f = patchForces({.cloud = c, .patches = {0}, .CofR = Vec3(0.5, 0, 0), .width = 0.3});
  EXPECT_NEAR(f.total.y(), -30.0, tol);  // 100 N/m over 0.3 m
  EXPECT_NEAR(f.momentTotal.z(), 0.0, 1e-10);  // symmetric about x = 0.5
}

TEST(PatchForces, OtherPatchesAndAnEmptySetGiveZero) {
  const ParticleCloud c = pptest::flatBed(10, 0.1, 100.0);
  const PatchForces f = patchForces({.cloud = c, .patches = {1}});
  EXPECT_EQ(f.nWall, 0);
  EXPECT_EQ(f.total, Vec3::Zero());
  EXPECT_EQ(f.meanNormal, Vec3::Zero());
}

TEST(PatchForces, DeviatoricStressIsTheTractionOnTheWall) {
  // Material sliding along +x over a bed: du/dy > 0, so τ_xy = 2η D_xy > 0 (tension positive).
  // It drags the bed along +x: F_d = Σ A τ·n = Σ dx (τ_xy, τ_yy) with n = +y.
  // A deviatoric compression normal to the bed (τ_yy < 0) pushes it down like a pressure.
  ParticleCloud c = pptest::flatBed(4, 0.1, 0.0);
  std::vector<SymmTensor> tau(c.size(), SymmTensor::Zero());
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] == static_cast<label>(ParticleKind::wall)) tau[i] << 0, 5, 0, -3, 0, 0;  // xx xy xz yy yz zz
  }
  const PatchForces f = patchForces({.cloud = c, .patches = {0}, .wallTau = &tau});
  EXPECT_NEAR(f.deviatoric.x(), 4 * 0.1 * 5, tol);
  EXPECT_NEAR(f.deviatoric.y(), 4 * 0.1 * -3, tol);
  EXPECT_NEAR(f.pressure.norm(), 0.0, tol);
  // t̂ = n̄ × ẑ = +x for a bed with the material above: the drag is a positive F_t.
  EXPECT_NEAR(f.tangent.x(), 1.0, tol);
  EXPECT_NEAR(f.tangential(f.deviatoric), 2.0, tol);
  EXPECT_NEAR(f.normal(f.deviatoric), 1.2, tol);
  EXPECT_NEAR(f.normal(f.total), 1.2, tol);
}

TEST(PatchForces, ASlidingMaterialActsByPressureAndFrictionOnly) {
  // The same bed and τ, with a friction traction t = (7, 0) Pa on each wall particle (a
  // material that slides, dragging the bed along +x): F_f = 4 × 0.1 × 7 = 2.8 N/m along +x,
  // F_d = 0 (the solver's walls do not act on a sliding material through τ), p = 20 Pa.
  ParticleCloud c = pptest::flatBed(4, 0.1, 20.0);
  std::vector<SymmTensor> tau(c.size(), SymmTensor::Zero());
  std::vector<Vec3> friction(c.size(), Vec3::Zero());
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] != static_cast<label>(ParticleKind::wall)) continue;
    tau[i] << 0, 5, 0, -3, 0, 0;
    friction[i] = Vec3(7, 0, 0);
  }
  const PatchForces f = patchForces({.cloud = c, .patches = {0}, .wallTau = &tau, .wallFriction = &friction});
  EXPECT_EQ(f.deviatoric, Vec3::Zero());
  EXPECT_NEAR(f.friction.x(), 2.8, tol);
  EXPECT_NEAR(f.normal(f.friction), 0.0, tol);
  EXPECT_NEAR(f.tangential(f.total), 2.8, tol);
  EXPECT_NEAR(f.normal(f.total), 4 * 0.1 * 20.0, tol);
  // Moment of the friction about the origin: the traction acts at y = 0, so none about z;
  // about CofR (0, 1): arm (x, −1) × (0.7, 0) = +0.7 per particle.
  EXPECT_NEAR(f.momentFriction.z(), 0.0, tol);
  const PatchForces g = patchForces({.cloud = c, .patches = {0}, .wallFriction = &friction, .CofR = Vec3(0, 1, 0)});
  EXPECT_NEAR(g.momentFriction.z(), 4 * 0.7, tol);
  EXPECT_NEAR(g.momentTotal.z(), g.momentPressure.z() + 4 * 0.7, tol);

  std::vector<Vec3> wrongSize(3);
  EXPECT_THROW(patchForces({.cloud = c, .patches = {0}, .wallFriction = &wrongSize}), FatalError);
}

// A barrier two spacings thick (as the barrier tutorial's at its test spacing): its upstream
// face (n = −x) at 300 Pa and its back face (n = +x) at 120 Pa, 5 particles each, dx = 0.1,
// its top (n = +y) at 50 Pa on 2. The whole patch nets (300 − 120) × 0.5 = 90 N/m along +x;
// `facing (-1 0 0)` takes the upstream face alone, 150 N/m, and `facing (1 1 0)` (45° off
// both the back face and the top, inside 60°) those two.
TEST(PatchForces, FacingSelectsOneFaceOfAStructure) {
  ParticleCloud c;
  c.properties.materials = {"sand"};
  c.properties.patches = {{"barrier", 0.0}};
  c.properties.spacing = 0.1;
  for (int i = 0; i < 5; ++i) {
    const double y = (i + 0.5) * 0.1;
    c.push_back(Vec3(2.3, y, 0), i, Vec3::Zero(), 300.0, -1, ParticleKind::wall, 0, Vec3(-1, 0, 0), 0);
    c.push_back(Vec3(2.5, y, 0), 10 + i, Vec3::Zero(), 120.0, -1, ParticleKind::wall, 0, Vec3(1, 0, 0), 0);
  }
  for (int i = 0; i < 2; ++i) {
    c.push_back(Vec3(2.35 + 0.1 * i, 0.5, 0), 20 + i, Vec3::Zero(), 50.0, -1, ParticleKind::wall, 0, Vec3(0, 1, 0), 0);
  }
  const PatchForces all = patchForces({.cloud = c, .patches = {0}});
  EXPECT_EQ(all.nWall, 12);
  EXPECT_NEAR(all.pressure.x(), 90.0, 1e-10);
  EXPECT_NEAR(all.pressure.y(), -10.0, 1e-10);
  const PatchForces upstream = patchForces({.cloud = c, .patches = {0}, .facing = Vec3(-1, 0, 0)});
  EXPECT_EQ(upstream.nWall, 5);
  EXPECT_NEAR(upstream.pressure.x(), 150.0, 1e-10);
  EXPECT_NEAR(upstream.pressure.y(), 0.0, 1e-10);
  EXPECT_NEAR(upstream.normal(upstream.total), 150.0, 1e-10) << "the face's own normal";
  const PatchForces lee = patchForces({.cloud = c, .patches = {0}, .facing = Vec3(1, 1, 0)});
  EXPECT_EQ(lee.nWall, 7);
  EXPECT_NEAR(lee.pressure.x(), -60.0, 1e-10);
  EXPECT_NEAR(lee.pressure.y(), -10.0, 1e-10);
}

TEST(PatchForces, VerticalWallSplitsIntoNormalAndTangential) {
  // A wall at x = 0 with material on its +x side (n = +x), p = 50 Pa on 5 particles dx = 0.2
  // and a shear τ_xy = 2: F_p = (−50, 0), F_d = A Σ (τ_xx, τ_xy) = (0, 2). t̂ = n̄ × ẑ = −y.
  ParticleCloud c;
  c.properties.materials = {"water"};
  c.properties.patches = {{"wall", 0.0}};
  c.properties.spacing = 0.2;
  for (int i = 0; i < 5; ++i) {
    c.push_back(Vec3(0, (i + 0.5) * 0.2, 0), i, Vec3::Zero(), 50.0, -1, ParticleKind::wall, 0, Vec3(1, 0, 0), 0);
  }
  std::vector<SymmTensor> tau(c.size());
  for (auto& t : tau) t << 0, 2, 0, 0, 0, 0;
  const PatchForces f = patchForces({.cloud = c, .patches = {0}, .wallTau = &tau});
  EXPECT_NEAR(f.pressure.x(), -50.0, tol);
  EXPECT_NEAR(f.deviatoric.y(), 2.0, tol);
  EXPECT_NEAR(f.tangent.y(), -1.0, tol);
  EXPECT_NEAR(f.normal(f.total), 50.0, tol);
  EXPECT_NEAR(f.tangential(f.total), -2.0, tol);
  // Moment about the origin of the pressure part: Σ y_i × 10 N/m (along +z) = 10 × 2.5 = 25 N m/m.
  EXPECT_NEAR(f.momentPressure.z(), 50 * 0.2 * (0.1 + 0.3 + 0.5 + 0.7 + 0.9), 1e-10);
}

TEST(PatchForces, BadInputIsAFatalError) {
  ParticleCloud c = pptest::flatBed(2, 0.1, 1.0);
  EXPECT_THROW(patchForces({.cloud = c, .patches = {2}}), FatalError);
  EXPECT_THROW(patchForces({.cloud = c, .patches = {0}, .width = 0.0}), FatalError);
  c.properties.spacing = 0;
  EXPECT_THROW(patchForces({.cloud = c, .patches = {0}}), FatalError);
}

}  // namespace
}  // namespace isph
