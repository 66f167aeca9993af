// The .dat columns of a force set: every column named with its unit, rows that read back to
// the forces, and the gnuplot script and PNG of -plot.
#include "postProcessing/forces/ForceTable.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "../PostProcessingTestHelpers.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "postProcessing/forces/ForcePlot.hpp"

namespace isph {
namespace {

ForceSet setFrom(const std::string& text) {
  return readForceSets(Dictionary::parse(text, "system/sampleForcesDict"))[0];
}

PatchForces sampleForces() {
  PatchForces f;
  f.pressure = Vec3(-100, 2, 0);
  f.deviatoric = Vec3(-1, 3, 0);
  f.friction = Vec3(0, 4, 0);
  f.total = f.pressure + f.deviatoric + f.friction;
  f.momentPressure = Vec3(0, 0, 7);
  f.momentDeviatoric = Vec3(0, 0, -2);
  f.momentFriction = Vec3(0, 0, 1);
  f.momentTotal = Vec3(0, 0, 6);
  f.meanNormal = Vec3(1, 0, 0);
  f.tangent = Vec3(0, -1, 0);
  f.nWall = 42;
  return f;
}

std::string lastLine(const std::string& text) {
  std::string line, last;
  std::istringstream in(text);
  while (std::getline(in, line)) last = line;
  return last;
}

TEST(ForceTable, HeaderNamesEveryColumnWithItsUnit) {
  const ForceTable perMetre(setFrom("wall { patches (left); }"), 2);
  const std::string h = perMetre.header(sampleForces());
  EXPECT_EQ(lastLine(h),
            "# Time [s]\tFx [N/m]\tFy [N/m]\tFn [N/m]\tFt [N/m]\tFpx [N/m]\tFpy [N/m]\tFpn [N/m]\tFpt [N/m]"
            "\tFdx [N/m]\tFdy [N/m]\tFdn [N/m]\tFdt [N/m]\tFfx [N/m]\tFfy [N/m]\tFfn [N/m]\tFft [N/m]"
            "\tMz [N m/m]\tMpz [N m/m]\tMdz [N m/m]\tMfz [N m/m]\tnWall [-]");
  EXPECT_NE(h.find("per metre of width"), std::string::npos);
  EXPECT_EQ(perMetre.column("Time"), 1);
  EXPECT_EQ(perMetre.column("Fn"), 4);
  EXPECT_EQ(perMetre.column("Fft"), 17);
  EXPECT_EQ(perMetre.column("Mz"), 18);

  const ForceTable wide(setFrom("wall { patches (left); width 0.3; }"), 2);
  EXPECT_NE(wide.header(sampleForces()).find("Fx [N]\t"), std::string::npos);
  EXPECT_NE(wide.header(sampleForces()).find("Mz [N m]\t"), std::string::npos);

  const ForceTable table3d(setFrom("wall { patches (left); }"), 3);
  EXPECT_EQ(table3d.columns().size(), 1u + 4 * 5 + 4 * 3 + 1);
  EXPECT_EQ(table3d.columns()[1].unit, "N");
}

TEST(ForceTable, RowHoldsTheForcesInColumnOrder) {
  const ForceTable t(setFrom("wall { patches (left); }"), 2);
  std::istringstream row(t.row(0.25, sampleForces()));
  std::vector<double> v;
  for (double x; row >> x;) v.push_back(x);
  const std::vector<double> expected{0.25, -101, 9, 101, -9, -100, 2, 100, -2, -1, 3, 1, -3, 0, 4, 0, -4, 6, 7, -2, 1, 42};
  ASSERT_EQ(v.size(), expected.size());
  for (std::size_t k = 0; k < v.size(); ++k) EXPECT_DOUBLE_EQ(v[k], expected[k]) << "column " << k + 1;
}

TEST(ForcePlot, ScriptPlotsTheNormalForceAndTheReference) {
  pptest::TempDir dir;
  pptest::writeText(dir / "ref.csv", "time,force\n0,1\n1,2\n");
  const ForceSet set = setFrom("wall { patches (left); reference \"ref.csv\"; }");
  const ForceTable t(set, 2);
  const std::string s = forcePlotScript(set, t, {.dat = dir / "wall.dat", .png = dir / "wall.png", .reference = dir / "ref.csv"});
  EXPECT_NE(s.find("using 1:4 with lines"), std::string::npos) << s;  // Fn
  EXPECT_NE(s.find("skip 1 using 1:2 with points"), std::string::npos) << s;
  EXPECT_NE(s.find("set datafile separator \"\\t,\""), std::string::npos) << s;
}

TEST(ForcePlot, DrawsAPngWhenGnuplotIsInstalled) {
  if (!gnuplotAvailable()) GTEST_SKIP() << "gnuplot is not installed";
  pptest::TempDir dir;
  const ForceSet set = setFrom("wall { patches (left); }");
  const ForceTable t(set, 2);
  std::string text = t.header(sampleForces());
  for (int k = 0; k < 5; ++k) text += t.row(0.1 * k, sampleForces());
  pptest::writeText(dir / "wall.dat", text);
  plotForces(set, t, {.dat = dir / "wall.dat", .png = dir / "wall.png", .reference = {}});
  const std::string png = pptest::readText(dir / "wall.png");
  ASSERT_GT(png.size(), 1000u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  std::size_t leftovers = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) leftovers += e.path().filename().string()[0] == '.';
  EXPECT_EQ(leftovers, 0u) << "temporary files left behind";
}

}  // namespace
}  // namespace isph
