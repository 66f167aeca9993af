// Collapse of a column of aluminium rods, 0.2 m long and 0.1 m high against a wall
// (tutorials/validation/columnCollapse, coarse: 5 mm spacing), phi = 19.8 deg, against the final
// surface measured by Bui et al. (2008) (tutorials/validation/columnCollapse/validation/, source
// in the file's header; third-party digitisation, +/- 2-3 mm). After 0.8 s the deposit must have
// its toe within 8 % of the measured 0.4423 m from the wall, a surface within 5 mm RMS of the
// measured one, and a static wedge against the wall: the height there within 10 % of the
// initial 0.1 m, and the rods near the top-left corner moved by less than dx.
//
// DISABLED until it passes (issue 5 stays open): the solver loses about a third of the
// deposit's volume in this collapse (free-surface rods at p = 0 clump), so the deposit comes
// out too flat and without its wedge; tutorials/validation/columnCollapse/README.md has the
// figures. Run it by hand with
//   build/tests/testIsphValidation --gtest_also_run_disabled_tests --gtest_filter='*ColumnCollapse*'
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "CaseRunner.hpp"
#include "particles/CloudIO.hpp"
#include "postProcessing/sampling/RunOut.hpp"
#include "postProcessing/sampling/SurfaceProfile.hpp"

namespace {

using isph::test::CaseRunner;
using namespace isph;

TEST(ColumnCollapse, DISABLED_FinalDepositFollowsBuiEtAl2008) {
  const double dx = 0.005, H = 0.1, measuredRunOut = 0.4423;
  const auto measured =
      readProfileCsv(std::string(ISPH_TUTORIALS) + "/columnCollapse/validation/granular_collapse_bui2008_final_surface.csv");
  ASSERT_GE(measured.size(), 10u);

  CaseRunner c("columnCollapse", "columnCollapse");
  c.set("system/particleMeshDict", "spacing", std::to_string(dx));
  c.set("system/controlDict", "endTime", "0.8");
  c.set("system/controlDict", "writeInterval", "0.1");
  ASSERT_NO_FATAL_FAILURE(c.meshAndSolve());
  EXPECT_EQ(c.logValue("isphLandslideFoam", "Wall crossings in the run:"), "0");

  const ParticleCloud start = readCloud(c.path() / "0", "particles");
  const ParticleCloud end = readCloud(c.path() / "0.8", "particles");

  RunOutSpec toe;
  toe.minNeighbours = 2;
  const auto runOutEnd = runOut(end, toe);
  ASSERT_TRUE(runOutEnd) << "no material left";

  SurfaceSpec bins;
  bins.binWidth = dx;
  bins.xMin = 0;
  bins.xMax = 0.6;
  const SurfaceProfile surface = surfaceProfile(end, bins);
  const double rms = rmsDistance(surface, measured);
  const double wallHeight = surface.height.front();

  // The wedge: rods that start within 0.02 m of the top-left corner (x = 0, y = H).
  std::map<label, Vec3> initial;
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (start.kind[i] == 0) initial[start.origId[i]] = start.positions[i];
  }
  double cornerMove = 0, maxSpeed = 0;
  int cornerRods = 0;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (end.kind[i] != 0) continue;
    maxSpeed = std::max(maxSpeed, end.U[i].norm());
    const Vec3& x0 = initial.at(end.origId[i]);
    if (x0.x() < 0.02 && x0.y() > H - 0.02) {
      ++cornerRods;
      cornerMove = std::max(cornerMove, (end.positions[i] - x0).norm());
    }
  }
  std::printf("toe %.4f m (measured %.4f m, %+.1f%%), surface RMS %.2f mm, height at the wall %.4f m, "
              "corner rods (%d) moved at most %.2f mm (dx %.1f mm), peak speed at 0.8 s %.3g m/s\n",
              *runOutEnd, measuredRunOut, 100 * (*runOutEnd / measuredRunOut - 1), 1e3 * rms, wallHeight, cornerRods,
              1e3 * cornerMove, 1e3 * dx, maxSpeed);
  for (const auto& p : measured) std::printf("  x %.4f  measured %.4f  computed %.4f\n", p.x, p.height, surface.heightAt(p.x));

  EXPECT_NEAR(*runOutEnd / measuredRunOut, 1.0, 0.08) << "final toe against the experiment";
  EXPECT_LT(rms, 0.005) << "RMS distance of the final surface to the measured one";
  EXPECT_NEAR(wallHeight / H, 1.0, 0.10) << "surface height at the wall (the static wedge)";
  ASSERT_GT(cornerRods, 0);
  EXPECT_LT(cornerMove, dx) << "the rods near the top-left corner must stay put";
}

}  // namespace
