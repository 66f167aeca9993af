// Thin granular layers on a plane with Coulomb bed friction δ = 25° (issue 55): sand (φ 33°,
// ρ 1500) in layers of 1, 2 and 4 particles at 5 mm, 0.6 m long, and slidingBlock's stiff block
// (10 rows of rock), on the slidingBlock tutorial's bed in the plane's frame (constant/g tilted),
// each at the tutorial's maxCo 0.2 and at 0.1 (maxDeltaT halved likewise: dt and dt/2).
// - At 45° (above δ) a layer slides as a Coulomb block: its centre of mass travels
//   s = ½ g (sin 45° − tan 25° cos 45°) t² = 0.4628 m in 0.5 s (elementary mechanics, as
//   tutorials/validation/slidingBlock/validation/), within 3 % (the goal), and the
//   travel changes by less than 1 % from dt to dt/2 (before issue 48's scheme set the 3-row
//   layer travelled +7.6 / +13.8 / +24.3 % at maxCo 0.2 / 0.1 / 0.05);
// - at 20° (below δ) a layer stays: the middle half of its length moves less than dx/4 in 1 s
//   (the creep limit). Its two free end faces slump, as a cohesionless face must (no
//   vertical face stands at φ 33°), so the ends are not judged.
// Layers that do not meet these goals yet run as DISABLED_ tests (below, with their figures;
// run them with --gtest_also_run_disabled_tests); doc/notes/thinLayers.md has every figure at
// maxCo 0.2, 0.1 and 0.05. Run-to-run noise: the cases are deterministic on one thread (the
// same figures to the printed digit on a rerun); the tolerances are the goals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <sstream>
#include <string>

#include "CaseRunner.hpp"
#include "particles/CloudIO.hpp"

namespace {

using isph::test::CaseRunner;
using isph::test::meanMaterialX;
using namespace isph;

constexpr double g = 9.81, dx = 0.005, delta = 25 * M_PI / 180;

struct Layer {
  const char* name;
  int rows;      // 0: slidingBlock's stiff block as it is (10 rows, 0.1 m long, rock)
  double angle;  // of the plane [deg]
};

// The slidingBlock tutorial turned into the layer on a plane at `angleDeg`, at maxCo 0.2/factor.
void prepare(CaseRunner& c, const Layer& layer, double angleDeg, double factor, double endTime) {
  const double theta = angleDeg * M_PI / 180;
  std::ostringstream gravity;
  gravity.precision(10);
  gravity << "value           (" << g * std::sin(theta) << " " << -g * std::cos(theta) << " 0);";
  ASSERT_NO_FATAL_FAILURE(c.replaceText("constant/g", "value           (4.905 -8.495709 0);", gravity.str()));
  ASSERT_NO_FATAL_FAILURE(c.replaceText("system/particleMeshDict", "frictionAngle 20;", "frictionAngle 25;"));
  if (layer.rows > 0) {
    ASSERT_NO_FATAL_FAILURE(c.replaceText("constant/materialProperties", "rock { model rigidPlastic; rho 2000; phi 60; etaMin 1e6; }",
                                          "rock { model rigidPlastic; rho 2000; phi 60; etaMin 1e6; }\n"
                                          "    sand { model rigidPlastic; rho 1500; phi 33; }"));
    std::ostringstream region;
    region << "block { type box; min (0.05 0 0); max (0.65 " << layer.rows * dx << " 0); material sand; }";
    ASSERT_NO_FATAL_FAILURE(c.replaceText("system/particleMeshDict",
                                          "block { type box; min (0.05 0 0); max (0.15 0.05 0); material rock; }",
                                          region.str()));
  }
  c.set("system/controlDict", "maxCo", std::to_string(0.2 / factor));
  c.set("system/controlDict", "maxDeltaT", std::to_string(2e-3 / factor));
  c.set("system/controlDict", "endTime", std::to_string(endTime));
}

// How ctest names a layer (without this, gtest prints the struct's bytes).
void PrintTo(const Layer& layer, std::ostream* os) { *os << layer.name << " at " << layer.angle << " deg"; }

// The largest displacement of the material particles that start in the middle half of the
// layer's length, away from its two end faces.
double largestMiddleDisplacement(const ParticleCloud& start, const ParticleCloud& end) {
  double lo = 1e30, hi = -1e30;
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (start.kind[i] != 0) continue;
    lo = std::min(lo, start.positions[i].x());
    hi = std::max(hi, start.positions[i].x());
  }
  const double quarter = 0.25 * (hi - lo);
  return isph::test::largestMaterialDisplacement(
      start, end, [&](const Vec3& x) { return x.x() > lo + quarter && x.x() < hi - quarter; });
}

class ThinLayerOnAPlane : public ::testing::TestWithParam<Layer> {};

TEST_P(ThinLayerOnAPlane, MovesAsCoulombSaysAtDtAndHalfDt) {
  const Layer& layer = GetParam();
  const double theta = layer.angle * M_PI / 180;
  const bool slides = theta > delta;
  const double t = slides ? 0.5 : 1.0;
  const double exact = 0.5 * g * (std::sin(theta) - std::tan(delta) * std::cos(theta)) * t * t;
  double first = 0;
  for (const double factor : {1.0, 2.0}) {
    CaseRunner c("slidingBlock", std::string("thinLayer-") + layer.name + "-" + std::to_string(int(factor)));
    ASSERT_NO_FATAL_FAILURE(prepare(c, layer, layer.angle, factor, t));
    ASSERT_NO_FATAL_FAILURE(c.meshAndSolve());
    const ParticleCloud start = readCloud(c.path() / "0", "particles");
    const ParticleCloud end = readCloud(c.path() / (slides ? "0.5" : "1"), "particles");
    const double travel = meanMaterialX(end) - meanMaterialX(start);
    if (slides) {
      std::printf("%s at %g deg, maxCo %.3g: travel %.4f m in %g s, Coulomb block %.4f m (%+.2f%%)\n", layer.name,
                  layer.angle, 0.2 / factor, travel, t, exact, 100 * (travel / exact - 1));
      EXPECT_NEAR(travel / exact, 1.0, 0.03) << layer.name << " at maxCo " << 0.2 / factor;
      if (factor == 1.0) first = travel;
      else EXPECT_NEAR(travel / first, 1.0, 0.01) << layer.name << ": not converged in the time step";
    } else {
      const double middle = largestMiddleDisplacement(start, end);
      std::printf("%s at %g deg, maxCo %.3g: centre of mass %.3g mm, middle half's largest displacement %.3g mm, "
                  "anywhere %.3g mm in 1 s (dx/4 = %.3g mm)\n",
                  layer.name, layer.angle, 0.2 / factor, 1e3 * travel, 1e3 * middle,
                  1e3 * isph::test::largestMaterialDisplacement(start, end), 250 * dx);
      EXPECT_LT(middle, 0.25 * dx) << layer.name << " crept at maxCo " << 0.2 / factor;
    }
  }
}

std::string layerName(const ::testing::TestParamInfo<Layer>& info) {
  return std::string(info.param.name) + "At" + std::to_string(int(info.param.angle));
}

INSTANTIATE_TEST_SUITE_P(Layers, ThinLayerOnAPlane,
                         ::testing::Values(Layer{"fourRows", 4, 45}, Layer{"stiffBlock", 0, 45}, Layer{"oneRow", 1, 20},
                                           Layer{"twoRows", 2, 20}),
                         layerName);

// Below the goals (measured 2026-12-06 at maxCo 0.2 / 0.1 / 0.05, converged in dt but
// not right, or not converged; issue 55 stays open on them):
// - one row at 45°: travel −6.4 / −6.1 / −5.9 % of Coulomb; two rows: −4.1 / −3.5 / −2.8 %;
// - four rows at 20°: the middle half moves 8.9 / 0.12 / 0.02 mm (the end faces' slump reaches
//   it at maxCo 0.2);
// - the stiff block at 20°: its middle half moves 9.6 / 6.1 / 3.8 mm, its bottom row 6.8 / 4.4 /
//   2.1 mm, though its centre of mass moves 0.03 mm.
INSTANTIATE_TEST_SUITE_P(DISABLED_BelowGoal, ThinLayerOnAPlane,
                         ::testing::Values(Layer{"oneRow", 1, 45}, Layer{"twoRows", 2, 45}, Layer{"fourRows", 4, 20},
                                           Layer{"stiffBlock", 0, 20}),
                         layerName);

}  // namespace
