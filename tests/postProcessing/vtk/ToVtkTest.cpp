// toVTK as a user runs it on a case with three times: the .vtp files read back with VTK's
// reader, and the .pvd lists every converted time in order whatever order they were converted.
#include <gtest/gtest.h>

#include "VtkTestHelpers.hpp"
#include "postProcessing/vtk/PvdCollection.hpp"

namespace isph {
namespace {

class ToVtk : public ::testing::Test {
 protected:
  pptest::TempDir dir;
  std::filesystem::path caseDir = dir / "tank";
  std::vector<ParticleCloud> clouds;

  void SetUp() override {
    clouds.push_back(pptest::writeSampleTime(caseDir, "0", 0.0));
    clouds.push_back(pptest::writeSampleTime(caseDir, "0.05", 0.05));
    clouds.push_back(pptest::writeSampleTime(caseDir, "0.1", 0.1));
  }
  int toVTK(const std::string& options) {
    return pptest::run(std::string(TOVTK_EXE) + " -case " + caseDir.string() + " " + options, dir / "log.toVTK");
  }
  std::vector<std::string> pvdTimes() {
    std::vector<std::string> out;
    for (const auto& e : readPvd(caseDir / "VTK/tank.pvd")) out.push_back(e.time);
    return out;
  }
};

TEST_F(ToVtk, PvdListsEveryConvertedTimeInOrder) {
  ASSERT_EQ(toVTK("-latestTime"), 0) << pptest::readText(dir / "log.toVTK");
  EXPECT_EQ(pvdTimes(), std::vector<std::string>{"0.1"});
  ASSERT_EQ(toVTK("-time 0"), 0) << pptest::readText(dir / "log.toVTK");
  EXPECT_EQ(pvdTimes(), (std::vector<std::string>{"0", "0.1"}));
  ASSERT_EQ(toVTK(""), 0) << pptest::readText(dir / "log.toVTK");
  EXPECT_EQ(pvdTimes(), (std::vector<std::string>{"0", "0.05", "0.1"}));
  const auto entries = readPvd(caseDir / "VTK/tank.pvd");
  EXPECT_EQ(entries[1].file, "tank_0.05.vtp");

  // Each file holds its own time's values.
  for (std::size_t t = 0; t < entries.size(); ++t) {
    const auto back = pptest::readVtp(caseDir / "VTK" / entries[t].file);
    ASSERT_EQ(back->GetNumberOfPoints(), static_cast<vtkIdType>(clouds[t].size()));
    for (std::size_t i = 0; i < clouds[t].size(); ++i) {
      EXPECT_EQ(back->GetPointData()->GetArray("p")->GetComponent(static_cast<vtkIdType>(i), 0), clouds[t].p[i]);
    }
    EXPECT_EQ(back->GetFieldData()->GetArray("TimeValue")->GetComponent(0, 0), std::stod(entries[t].time));
  }
  // Nothing half-written or temporary is left in VTK/.
  for (const auto& e : std::filesystem::directory_iterator(caseDir / "VTK")) {
    EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
  }
}

TEST_F(ToVtk, FieldsNoWallsAndAscii) {
  ASSERT_EQ(toVTK("-time 0.05 -fields '(p U)' -noWalls -ascii"), 0) << pptest::readText(dir / "log.toVTK");
  const std::string text = pptest::readText(caseDir / "VTK/tank_0.05.vtp");
  EXPECT_NE(text.find("format=\"ascii\""), std::string::npos);
  const auto back = pptest::readVtp(caseDir / "VTK/tank_0.05.vtp");
  EXPECT_EQ(back->GetNumberOfPoints(), 4);
  vtkPointData* pd = back->GetPointData();
  EXPECT_EQ(pd->GetNumberOfArrays(), 4);  // p, U, magU, stress
  EXPECT_NE(pd->GetArray("stress"), nullptr);
  EXPECT_EQ(pd->GetArray("kind"), nullptr);
}

TEST_F(ToVtk, BadFieldsOptionIsAnErrorNamingIt) {
  EXPECT_NE(toVTK("-fields '(p U'"), 0);
  EXPECT_NE(pptest::readText(dir / "log.toVTK").find("-fields"), std::string::npos)
      << pptest::readText(dir / "log.toVTK");
  EXPECT_FALSE(std::filesystem::exists(caseDir / "VTK/tank.pvd"));
}

}  // namespace
}  // namespace isph
