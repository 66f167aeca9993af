// A whole cloud written into a time directory and read back: every field, both formats,
// and the material and patch names the labels index.
#include "particles/CloudIO.hpp"

#include "core/Error.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

namespace isph {
namespace {

class CloudIOTest : public ::testing::TestWithParam<WriteFormat> {
 protected:
  std::filesystem::path dir = std::filesystem::temp_directory_path() /
                              ("isph_cloudio_" + std::to_string(::getpid()) + "_" +
                               std::to_string(static_cast<int>(GetParam())));
  void SetUp() override { std::filesystem::create_directories(dir); }
  void TearDown() override { std::filesystem::remove_all(dir); }
};

ParticleCloud sampleCloud() {
  ParticleCloud c;
  c.properties.materials = {"sand", "weakLayer"};
  c.properties.patches = {{"bed", 25.0}, {"barrier", 18.5}};
  c.properties.spacing = 0.0036;
  c.properties.lattice = "hexagonal";
  c.push_back(Vec3(0.1, 0.2, 0), 0, Vec3(1, 2, 0), 123.456789012345, 0, ParticleKind::material, -1, Vec3::Zero(), 0.0179);
  c.push_back(Vec3(0.3, 0.0, 0), 1, Vec3::Zero(), 0.5, 1, ParticleKind::material, -1, Vec3::Zero(), 0.02);
  c.push_back(Vec3(0.3, -0.0036, 0), 2, Vec3::Zero(), 0.0, -1, ParticleKind::wall, 0, Vec3(0, 1, 0), 0.0);
  c.push_back(Vec3(0.3, -0.0072, 0), 3, Vec3::Zero(), 0.0, -1, ParticleKind::dummy, 1, Vec3::Zero(), 0.0);
  return c;
}

TEST_P(CloudIOTest, RoundTripKeepsEveryFieldAndTheNames) {
  const ParticleCloud c = sampleCloud();
  writeCloud(dir / "0", "0", c, FieldWriteOptions{GetParam(), 17, ""});
  const ParticleCloud back = readCloud(dir / "0", "particles");
  ASSERT_EQ(back.size(), c.size());
  EXPECT_EQ(back.positions, c.positions);
  EXPECT_EQ(back.U, c.U);
  EXPECT_EQ(back.p, c.p);
  EXPECT_EQ(back.mass, c.mass);
  EXPECT_EQ(back.origId, c.origId);
  EXPECT_EQ(back.material, c.material);
  EXPECT_EQ(back.kind, c.kind);
  EXPECT_EQ(back.patch, c.patch);
  EXPECT_EQ(back.normal, c.normal);
  EXPECT_EQ(back.properties.materials, c.properties.materials);
  ASSERT_EQ(back.properties.patches.size(), 2u);
  EXPECT_EQ(back.properties.patches[1].name, "barrier");
  EXPECT_DOUBLE_EQ(back.properties.patches[1].frictionAngle, 18.5);
  EXPECT_DOUBLE_EQ(back.properties.spacing, 0.0036);
  EXPECT_EQ(back.properties.lattice, "hexagonal");
}

TEST_P(CloudIOTest, MissingCloudAndBadLabelsAreClearErrors) {
  EXPECT_THROW(readCloud(dir / "0", "particles"), FatalError);
  ParticleCloud c = sampleCloud();
  c.material[1] = 7;  // no such material
  writeCloud(dir / "0", "0", c, FieldWriteOptions{GetParam(), 8, ""});
  try {
    readCloud(dir / "0", "particles");
    FAIL();
  } catch (const FatalError& e) {
    EXPECT_NE(std::string(e.what()).find("particle 1"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, CloudIOTest, ::testing::Values(WriteFormat::ascii, WriteFormat::binary));

}  // namespace
}  // namespace isph
