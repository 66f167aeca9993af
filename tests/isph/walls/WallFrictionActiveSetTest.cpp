// The stick/slip iteration of WallFrictionActiveSet on one particle resting on a horizontal
// friction wall (2D, n = +y), with its velocity system solved exactly: per unit of time step,
//   (m/dt + B_xx) u_x = (m/dt) v + f_x,
// v the tangential velocity the particle would reach without friction, B and f the active
// set's block and force. The regularised Coulomb law has the exact answer
//   stick (u_x = (m/dt) v / (m/dt + F/u_slip))  if (m/dt) |v| <= F + (m/dt) u_slip,
//   slide (u_x = v - sign(v) F dt/m)              otherwise,
// which the passes must reach in two (three when the particle starts sliding the wrong way).
#include <gtest/gtest.h>

#include <cmath>

#include "isph/walls/WallFrictionActiveSet.hpp"

namespace {

using namespace isph;

constexpr double m = 1.0, dt = 1e-3, F = 5.0, uSlip = 1e-4;
constexpr double M = m / dt;

struct Outcome {
  double u;
  int passes;
  WallFrictionActiveSet::State state;
};

// Passes from the velocity at time n (un) for the driving velocity v, until no state changes.
Outcome iterate(WallFrictionActiveSet& set, double un, double v, label id = 0) {
  set.start({F}, {Vec3(0, 1, 0)}, uSlip, {Vec3(un, 0, 0)}, {id});
  for (int pass = 1; pass <= 10; ++pass) {
    const double u = (M * v + set.force(0).x()) / (M + set.block(0, 0, 0));
    EXPECT_NEAR(set.block(0, 1, 1), 0.0, 1e-12) << "friction acts on the tangential velocity only";
    EXPECT_NEAR(set.block(0, 0, 1), 0.0, 1e-12);
    if (set.update({u, 0.0}, 2) == 0) return {u, pass, set.state(0)};
  }
  return {NAN, 11, set.state(0)};
}

double exact(double v) {
  if (M * std::abs(v) <= F + M * uSlip) return M * v / (M + F / uSlip);
  return v - std::copysign(F / M, v);
}

TEST(WallFrictionActiveSet, OneParticleReachesTheCoulombAnswerInTwoPassesFromEitherState) {
  // The threshold of the driving velocity is F dt/m + u_slip = 5.1e-3 m/s.
  for (double v : {0.001, 0.004, 0.0050, 0.0052, 0.02, 0.5, -0.004, -0.02}) {
    for (double un : {0.0, 0.01 * std::copysign(1.0, v)}) {  // at rest, or sliding the same way
      WallFrictionActiveSet set;
      const Outcome o = iterate(set, un, v);
      EXPECT_LE(o.passes, 2) << "v " << v << ", from " << un;
      EXPECT_NEAR(o.u, exact(v), 1e-12 + 1e-9 * std::abs(v)) << "v " << v << ", from " << un;
      const bool sticks = M * std::abs(v) <= F + M * uSlip;
      EXPECT_EQ(o.state, sticks ? WallFrictionActiveSet::State::stick : WallFrictionActiveSet::State::slide) << v;
    }
  }
}

TEST(WallFrictionActiveSet, SlidingTheWrongWayTakesThreePasses) {
  WallFrictionActiveSet set;
  const Outcome o = iterate(set, -0.01, 0.02);  // slide -x → stick → slide +x
  EXPECT_EQ(o.passes, 3);
  EXPECT_NEAR(o.u, exact(0.02), 1e-12);
}

TEST(WallFrictionActiveSet, StatesCarryOverToTheNextStepByOrigId) {
  // Two particles, 7 sliding fast and 3 stuck; next step they come in the other order with
  // velocities that alone would classify them the other way round: the kept states win.
  WallFrictionActiveSet set;
  const std::vector<double> capacity{F, F};
  const std::vector<Vec3> normal{Vec3(0, 1, 0), Vec3(0, 1, 0)};
  set.start(capacity, normal, uSlip, {Vec3(0.5, 0, 0), Vec3(0, 0, 0)}, {7, 3});
  ASSERT_EQ(set.state(0), WallFrictionActiveSet::State::slide);
  ASSERT_EQ(set.state(1), WallFrictionActiveSet::State::stick);
  set.remember({7, 3});
  set.start(capacity, normal, uSlip, {Vec3(0.5, 0, 0), Vec3(0, 0, 0)}, {3, 7});
  EXPECT_EQ(set.state(0), WallFrictionActiveSet::State::stick);   // id 3
  EXPECT_EQ(set.state(1), WallFrictionActiveSet::State::slide);   // id 7
  EXPECT_NEAR(set.force(1).x(), -F, 1e-12);                        // against its slip, +x
  // A particle that has left the wall (capacity 0) is free: no block, no force.
  set.start({0.0, F}, normal, uSlip, {Vec3(0, 0, 0), Vec3(0, 0, 0)}, {7, 3});
  EXPECT_EQ(set.state(0), WallFrictionActiveSet::State::free);
  EXPECT_EQ(set.block(0, 0, 0), 0.0);
  EXPECT_EQ(set.force(0).norm(), 0.0);
}

}  // namespace
