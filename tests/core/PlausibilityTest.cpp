// The unit slips of issue 53 (phi 0.768, rho 1.379, g (0 -98.1 0)) warn; usual values do not;
// the slope g implies.
#include "core/Plausibility.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

namespace isph {
namespace {

int warningsOf(const std::function<void()>& f, std::string* text = nullptr) {
  const int before = warningCount();
  testing::internal::CaptureStderr();
  f();
  const std::string err = testing::internal::GetCapturedStderr();
  if (text) *text = err;
  return warningCount() - before;
}

TEST(Plausibility, FrictionAngles) {
  std::string err;
  EXPECT_EQ(warningsOf([] { warnIfImplausibleFrictionAngle(0.768, "material 'sand': phi", {}); }, &err), 1);
  EXPECT_NE(err.find("radians? 0.768 rad is 44"), std::string::npos) << err;
  EXPECT_EQ(warningsOf([] { warnIfImplausibleFrictionAngle(61, "phi", {}); }), 1);
  EXPECT_EQ(warningsOf([] { warnIfImplausibleFrictionAngle(4.9, "phi", {}); }), 1);
  EXPECT_EQ(warningsOf([] { warnIfImplausibleFrictionAngle(5, "phi", {}); }), 0);
  EXPECT_EQ(warningsOf([] { warnIfImplausibleFrictionAngle(44, "phi", {}); }), 0);
  EXPECT_EQ(warningsOf([] { warnIfImplausibleFrictionAngle(60, "phi", {}); }), 0);
  // a frictionless wall is deliberate
  EXPECT_EQ(warningsOf([] { warnIfImplausibleFrictionAngle(0, "wall 'bed': frictionAngle", {}, true); }), 0);
  EXPECT_EQ(warningsOf([] { warnIfImplausibleFrictionAngle(0.4, "wall 'bed': frictionAngle", {}, true); }), 1);
}

TEST(Plausibility, Densities) {
  std::string err;
  EXPECT_EQ(warningsOf([] { warnIfImplausibleDensity(1.379, "material 'sand': rho", {}); }, &err), 1);
  EXPECT_NE(err.find("g/cm^3? that is 1379 kg/m^3"), std::string::npos) << err;
  EXPECT_EQ(warningsOf([] { warnIfImplausibleDensity(499, "rho", {}); }), 1);
  EXPECT_EQ(warningsOf([] { warnIfImplausibleDensity(5001, "rho", {}); }), 1);
  EXPECT_EQ(warningsOf([] { warnIfImplausibleDensity(1000, "rho", {}); }), 0);
  EXPECT_EQ(warningsOf([] { warnIfImplausibleDensity(2650, "rho", {}); }), 0);
}

TEST(Plausibility, GravityWithinOnePercent) {
  EXPECT_EQ(warningsOf([] { warnIfImplausibleGravity(Vec3(0, -98.1, 0), {}); }), 1);
  EXPECT_EQ(warningsOf([] { warnIfImplausibleGravity(Vec3(0, -9.70, 0), {}); }), 1);   // 1.1 % low
  EXPECT_EQ(warningsOf([] { warnIfImplausibleGravity(Vec3(0, -9.72, 0), {}); }), 0);   // 0.9 % low
  EXPECT_EQ(warningsOf([] { warnIfImplausibleGravity(Vec3(6.936718, -6.936718, 0), {}); }), 0);
}

TEST(Plausibility, SlopeFromGravity) {
  EXPECT_NEAR(slopeFromGravity(Vec3(6.936718, -6.936718, 0)), 45, 1e-6);
  const double t = 55 * std::acos(-1.0) / 180;
  EXPECT_NEAR(slopeFromGravity(Vec3(9.81 * std::sin(t), -9.81 * std::cos(t), 0)), 55, 1e-9);
  EXPECT_NEAR(slopeFromGravity(Vec3(0, -9.81, 0)), 0, 1e-12);
}

}  // namespace
}  // namespace isph
