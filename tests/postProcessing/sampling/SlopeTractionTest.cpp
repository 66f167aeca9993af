#include "postProcessing/sampling/SlopeTraction.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "core/Error.hpp"
#include "TwentyDegreeLayer.hpp"

namespace {

using namespace isph;

// A 60 x 10 layer of sand (rho 1800) on a 0.01 m lattice, x in (0, 0.6), top centres at
// y = 0.095 (real surface 0.1), under gravity tilted by 20 degrees. Statics: sigma_nn =
// rho |g| cos(beta) d and sigma_nt = rho |g| sin(beta) d, d = 0.1 - y. The mean pressure is
// statically undetermined: the layer is given p = K0 sigma_nn with K0 = 0.6, and tau_yy =
// p - sigma_nn so that p - tau_yy is the statics' sigma_nn whatever K0 is.
using namespace isph::test;
constexpr double K0 = 0.6;

struct Layer {
  ParticleCloud cloud;
  std::vector<SymmTensor> tau;
};

double depth(double y) { return H - y; }

Layer layer() {
  Layer l;
  l.cloud.properties.spacing = 0.01;
  label id = 0;
  for (int i = 0; i < 60; ++i)
    for (int j = 0; j < 10; ++j) {
      const double y = 0.005 + 0.01 * j;
      const double sigmaNN = rho * gMag * std::cos(beta) * depth(y);
      const double p = K0 * sigmaNN;
      l.cloud.push_back(Vec3(0.005 + 0.01 * i, y, 0), id++, Vec3::Zero(), p, 0, ParticleKind::material, -1,
                        Vec3::Zero(), 0.18);
      SymmTensor t = SymmTensor::Zero();
      t[3] = p - sigmaNN;                               // tau_yy
      t[0] = -t[3];                                     // tau_xx (traceless in the plane)
      t[1] = rho * gMag * std::sin(beta) * depth(y);    // tau_xy
      l.tau.push_back(t);
    }
  // A wall particle with a wild pressure and stress: never counted.
  l.cloud.push_back(Vec3(0.3, -0.005, 0), id++, Vec3::Zero(), 1e9, -1, ParticleKind::wall, 0, Vec3::UnitY(), 0);
  SymmTensor wild = SymmTensor::Constant(1e9);
  l.tau.push_back(wild);
  return l;
}

LithostaticSpec spec() { return twentyDegreeLayerSpec(); }

TEST(SlopeTraction, StaticsHoldWhateverTheMeanPressure) {
  const Layer l = layer();
  const SlopeTractionError e = slopeTractionError(l.cloud, l.tau, spec());
  EXPECT_LT(e.l2Normal, 1e-12);
  EXPECT_LT(e.l2Shear, 1e-12);
  EXPECT_LT(e.spreadNormal, 1e-12);
  EXPECT_LT(e.spreadShear, 1e-12);
  EXPECT_EQ(e.interior, 30u * 8u) << "30 columns inside 0.15 < x < 0.45; 8 rows whose upper edge is deeper than 0.015 m";
}

TEST(SlopeTraction, AShearTooLargeByTenPercentIsATenPercentShearError) {
  Layer l = layer();
  for (std::size_t i = 0; i + 1 < l.tau.size(); ++i) l.tau[i][1] *= 1.1;
  const SlopeTractionError e = slopeTractionError(l.cloud, l.tau, spec());
  EXPECT_NEAR(e.l2Shear, 0.1, 1e-12);
  EXPECT_LT(e.l2Normal, 1e-12) << "the normal traction does not see tau_xy";
}

TEST(SlopeTraction, ThePressureAloneMovesTheNormalTraction) {
  Layer l = layer();
  const double bump = 0.01 * rho * gMag * H;  // 1 % of rho |g| H
  l.cloud.p[30 * 10 + 4] += bump;            // x = 0.305, y = 0.045: inside
  l.cloud.p[2 * 10 + 4] += 10 * bump;        // by the end wall: outside the interior
  const SlopeTractionError e = slopeTractionError(l.cloud, l.tau, spec());
  EXPECT_NEAR(e.spreadNormal, 0.01, 1e-12);
  EXPECT_GT(e.l2Normal, 0.0);
  EXPECT_LT(e.l2Shear, 1e-12);
}

TEST(SlopeTraction, CountsTheParticlesAtTheRigidPlasticStrength) {
  // phi = 30 deg: the strength is sin(phi) (p + rho |g| dx / 2) (DruckerPragerRigidPlastic).
  Layer l = layer();
  const double sinPhi = 0.5, floor = 0.5 * rho * gMag * 0.01;
  for (auto& t : l.tau) t = SymmTensor::Zero();
  for (std::size_t i = 0; i < 60; ++i) {  // the bed row of every column: at yield
    const std::size_t a = i * 10;
    l.tau[a] = SymmTensor::Zero();
    l.tau[a][1] = sinPhi * (l.cloud.p[a] + floor);
  }
  EXPECT_NEAR(slopeTractionError(l.cloud, l.tau, spec(), 30.0).atYield, 0.1, 1e-12);
  EXPECT_EQ(slopeTractionError(l.cloud, l.tau, spec(), 0.0).atYield, 0.0) << "no yield count without phi";
}

TEST(SlopeTraction, RefusesAStressOfAnotherSize) {
  Layer l = layer();
  l.tau.pop_back();
  EXPECT_THROW(slopeTractionError(l.cloud, l.tau, spec()), FatalError);
}

}  // namespace
