// A cloud written as .vtp (binary compressed and ascii) and read back with VTK's reader:
// points, every field, the derived |U| and stress, the names, -noWalls and -fields.
#include "postProcessing/vtk/CloudPolyData.hpp"

#include <gtest/gtest.h>

#include "VtkTestHelpers.hpp"
#include "postProcessing/vtk/VtpFile.hpp"

namespace isph {
namespace {

class CloudPolyDataTest : public ::testing::TestWithParam<VtkFormat> {};

TEST_P(CloudPolyDataTest, EveryFieldReadsBackWithVtksReader) {
  pptest::TempDir dir;
  const ParticleCloud c = pptest::writeSampleTime(dir.path(), "0.1", 0.1);
  const CloudFields fields = readCloudFields(dir / "0.1", "particles");
  EXPECT_EQ(fields.available, (std::vector<std::string>{"U", "freeSurface", "kind", "mass", "material", "normal",
                                                         "origId", "p", "patch", "tau"}));
  writeVtp(cloudPolyData(fields, 0.1, {}), dir / "c.vtp", GetParam());
  if (GetParam() == VtkFormat::ascii) {
    EXPECT_NE(pptest::readText(dir / "c.vtp").find("format=\"ascii\""), std::string::npos);
  } else {
    const std::string text = pptest::readText(dir / "c.vtp");
    EXPECT_NE(text.find("vtkZLibDataCompressor"), std::string::npos);
    EXPECT_NE(text.find("format=\"appended\""), std::string::npos);
  }

  const auto back = pptest::readVtp(dir / "c.vtp");
  ASSERT_EQ(back->GetNumberOfPoints(), static_cast<vtkIdType>(c.size()));
  EXPECT_EQ(back->GetNumberOfVerts(), static_cast<vtkIdType>(c.size()));
  vtkPointData* pd = back->GetPointData();
  for (const char* name : {"U", "freeSurface", "kind", "mass", "material", "normal", "origId", "p", "patch", "tau",
                           "magU", "stress"}) {
    EXPECT_NE(pd->GetArray(name), nullptr) << name;
  }
  ASSERT_NE(pd->GetArray("stress"), nullptr);
  ASSERT_NE(pd->GetArray("tau"), nullptr);
  EXPECT_EQ(pd->GetArray("tau")->GetNumberOfComponents(), 9);
  for (std::size_t i = 0; i < c.size(); ++i) {
    const auto k = static_cast<vtkIdType>(i);
    double x[3];
    back->GetPoint(k, x);
    EXPECT_EQ(Vec3(x[0], x[1], x[2]), c.positions[i]);
    EXPECT_EQ(pd->GetArray("p")->GetComponent(k, 0), c.p[i]) << "binary and 17-digit ascii are exact";
    EXPECT_EQ(pd->GetArray("U")->GetComponent(k, 1), c.U[i].y());
    EXPECT_EQ(pd->GetArray("kind")->GetComponent(k, 0), c.kind[i]);
    EXPECT_EQ(pd->GetArray("origId")->GetComponent(k, 0), c.origId[i]);
    EXPECT_EQ(pd->GetArray("freeSurface")->GetComponent(k, 0), static_cast<double>(i % 2));
    EXPECT_NEAR(pd->GetArray("magU")->GetComponent(k, 0), std::sqrt(5.0) * static_cast<double>(i), 1e-12);
    // tau = i (xx xy xz yy yz zz) = i (1 2 3 4 5 6): full tensor row by row.
    const double di = static_cast<double>(i);
    const double full[9] = {1, 2, 3, 2, 4, 5, 3, 5, 6};
    for (int m = 0; m < 9; ++m) {
      EXPECT_EQ(pd->GetArray("tau")->GetComponent(k, m), di * full[m]) << "component " << m;
      const double pressure = (m == 0 || m == 4 || m == 8) ? c.p[i] : 0.0;
      EXPECT_NEAR(pd->GetArray("stress")->GetComponent(k, m), di * full[m] - pressure, 1e-12) << "component " << m;
    }
  }
  EXPECT_EQ(pptest::stringsOf(back, "materialNames"), std::vector<std::string>{"water"});
  EXPECT_EQ(pptest::stringsOf(back, "patchNames"), (std::vector<std::string>{"bed", "barrier"}));
  EXPECT_EQ(pptest::stringsOf(back, "kindNames"), (std::vector<std::string>{"material", "wall", "dummy"}));
  ASSERT_NE(back->GetFieldData()->GetArray("TimeValue"), nullptr);
  EXPECT_EQ(back->GetFieldData()->GetArray("TimeValue")->GetComponent(0, 0), 0.1);
}

INSTANTIATE_TEST_SUITE_P(Formats, CloudPolyDataTest, ::testing::Values(VtkFormat::binary, VtkFormat::ascii),
                         [](const auto& info) { return info.param == VtkFormat::ascii ? "ascii" : "binary"; });

TEST(CloudPolyData, NoWallsKeepsOnlyMaterialAndFieldsSelects) {
  pptest::TempDir dir;
  const ParticleCloud c = pptest::writeSampleTime(dir.path(), "0", 0.0);
  const CloudFields some = readCloudFields(dir / "0", "particles", std::vector<std::string>{"U", "freeSurface"});
  writeVtp(cloudPolyData(some, 0.0, {.noWalls = true}), dir / "c.vtp");
  const auto back = pptest::readVtp(dir / "c.vtp");
  EXPECT_EQ(back->GetNumberOfPoints(), 4);  // the material particles of flatBed(4, ...)
  vtkPointData* pd = back->GetPointData();
  EXPECT_EQ(pd->GetNumberOfArrays(), 3);  // U, freeSurface, magU
  EXPECT_EQ(pd->GetArray("p"), nullptr);
  EXPECT_EQ(pd->GetArray("stress"), nullptr);
  ASSERT_NE(pd->GetArray("U"), nullptr);
  vtkIdType k = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c.kind[i] != static_cast<label>(ParticleKind::material)) continue;
    EXPECT_EQ(pd->GetArray("U")->GetComponent(k, 0), c.U[i].x());
    EXPECT_EQ(pd->GetArray("freeSurface")->GetComponent(k, 0), static_cast<double>(i % 2));
    ++k;
  }
}

}  // namespace
}  // namespace isph
