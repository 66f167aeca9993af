// Validation: water at rest in a tank made by particleMesh (initialPressure lithostatic) pushes
// on its vertical wall with ½ ρ g H² per metre of width, within 2 %, at two resolutions; the
// sampleForces utility writes the same force as the library routine.
//
// particleMesh gives lithostatic pressure to material particles only (walls get 0); the solver
// solves for the wall pressure. Here the wall particles get the same lithostatic pressure,
// p = ρ |g| max(H − y, 0), and the cloud is written back before sampleForces runs.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>

#include "../PostProcessingTestHelpers.hpp"
#include "particles/CloudIO.hpp"
#include "postProcessing/forces/PatchForces.hpp"

namespace isph {
namespace {

constexpr double rho = 1000, g = 9.81, H = 1.0;
const double exactForce = 0.5 * rho * g * H * H;          // 4905 N/m
// The water, on the wall's +x side, pushes it along −x at height H/3: about the wall's foot
// M_z = (y ŷ) × (−F x̂) = +F H/3 = ρ g H³ / 6.
const double exactMoment = rho * g * H * H * H / 6.0;

struct TankResult {
  double force = 0, moment = 0, fy = 0, utilityForce = 0, utilitySideWalls = 0;
  long nWall = 0;
};

std::vector<double> lastRow(const std::string& text) {
  std::string line, last;
  std::istringstream in(text);
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] != '#') last = line;
  }
  std::istringstream row(last);
  std::vector<double> v;
  for (double x; row >> x;) v.push_back(x);
  return v;
}

TankResult runTank(const pptest::TempDir& dir, double dx) {
  const auto caseDir = dir / "tank";
  std::filesystem::copy(std::string(ISPH_TEST_CASES) + "/hydrostaticTank", caseDir,
                        std::filesystem::copy_options::recursive);
  const auto dictFile = caseDir / "system/particleMeshDict";
  pptest::writeText(dictFile, std::regex_replace(pptest::readText(dictFile), std::regex("spacing +0.01;"),
                                                 "spacing " + std::to_string(dx) + ";"));
  const int rc = pptest::run(std::string(PARTICLEMESH_EXE) + " -case " + caseDir.string(), dir / "log.particleMesh");
  EXPECT_EQ(rc, 0) << pptest::readText(dir / "log.particleMesh");

  // The wall particles get the lithostatic pressure of the water column beside them.
  ParticleCloud cloud = readCloud(caseDir / "0", "particles");
  EXPECT_NEAR(cloud.properties.spacing, dx, 1e-15);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] == static_cast<label>(ParticleKind::wall)) {
      cloud.p[i] = rho * g * std::max(H - cloud.positions[i].y(), 0.0);
    }
  }
  writeCloud(caseDir / "0", "0", cloud, FieldWriteOptions{WriteFormat::binary, 17, ""});

  TankResult r;
  const label left = 1;  // bed, leftWall, rightWall in the order of particleMeshDict
  EXPECT_EQ(cloud.properties.patches[left].name, "leftWall");
  const PatchForces f = patchForces({.cloud = cloud, .patches = {left}});
  r.force = f.normal(f.total);
  r.moment = f.momentTotal.z();
  r.fy = f.total.y();
  r.nWall = f.nWall;
  EXPECT_NEAR(f.total.x(), -r.force, 1e-9 * exactForce) << "the wall's normal is +x: pushed along −x";

  const int rc2 = pptest::run(std::string(SAMPLEFORCES_EXE) + " -case " + caseDir.string(), dir / "log.sampleForces");
  EXPECT_EQ(rc2, 0) << pptest::readText(dir / "log.sampleForces");
  const auto leftRow = lastRow(pptest::readText(caseDir / "postProcessing/sampleForces/0/leftWall.dat"));
  const auto sideRow = lastRow(pptest::readText(caseDir / "postProcessing/sampleForces/0/sideWalls.dat"));
  EXPECT_EQ(leftRow.size(), 22u);  // the 2D columns of ForceTable.hpp
  EXPECT_EQ(sideRow.size(), 22u);
  if (leftRow.size() > 3) r.utilityForce = leftRow[3];      // Fn
  if (sideRow.size() > 1) r.utilitySideWalls = sideRow[1];  // Fx
  return r;
}

class HydrostaticTank : public ::testing::TestWithParam<double> {};

TEST_P(HydrostaticTank, VerticalWallForceIsHalfRhoGHSquared) {
  pptest::TempDir dir;
  const double dx = GetParam();
  const TankResult r = runTank(dir, dx);
  const double error = (r.force - exactForce) / exactForce;
  std::cout << "dx = " << dx << ": F = " << r.force << " N/m on " << r.nWall << " wall particles, exact "
            << exactForce << ", error " << 100 * error << " %; moment " << r.moment << " N m/m, exact "
            << exactMoment << "\n";
  RecordProperty("relativeError", std::to_string(error));
  EXPECT_LT(std::abs(error), 0.02);
  // Wall particles dx apart from y = dx: the sum misses the stretch [0, dx/2] next to the bed
  // corner, an error of −dx/H: the bound above is met because it shrinks with dx.
  EXPECT_NEAR(error, -dx / H, 1e-6);
  EXPECT_NEAR(r.moment, exactMoment, 0.002 * std::abs(exactMoment));
  EXPECT_NEAR(r.fy, 0.0, 1e-9 * exactForce);
  // The utility writes what the routine gives (8 significant digits in the .dat).
  EXPECT_NEAR(r.utilityForce, r.force, 1e-7 * exactForce);
  // Both side walls of a 0.3 m wide tank: equal and opposite.
  EXPECT_NEAR(r.utilitySideWalls, 0.0, 1e-7 * exactForce);
}

INSTANTIATE_TEST_SUITE_P(TwoResolutions, HydrostaticTank, ::testing::Values(0.01, 0.005),
                         [](const auto& info) { return info.param == 0.01 ? "dx10mm" : "dx5mm"; });

}  // namespace
}  // namespace isph
