// readFieldInfo and listFields: what a cloud folder holds, without reading the values.
#include <gtest/gtest.h>

#include "../io/IoTestHelpers.hpp"
#include "core/fields/FieldIO.hpp"

namespace isph {
namespace {

using iotest::TempDir;
using iotest::writeText;

TEST(FieldFiles, ReadFieldInfo) {
  TempDir tmp;
  writeField(tmp / "U", std::vector<Vec3>(7, Vec3(1, 2, 3)),
             {WriteFormat::binary, 6, "0/lagrangian/particles"});
  FieldFileInfo info = readFieldInfo(tmp / "U");
  EXPECT_EQ(info.className, "vectorField");
  EXPECT_EQ(info.object, "U");
  EXPECT_EQ(info.format, WriteFormat::binary);
  EXPECT_EQ(info.size, 7u);
  EXPECT_FALSE(info.uniform);

  writeField(tmp / "origId", std::vector<label>{1, 2, 3}, {});
  info = readFieldInfo(tmp / "origId");
  EXPECT_EQ(info.className, "labelField");
  EXPECT_EQ(info.format, WriteFormat::ascii);
  EXPECT_EQ(info.size, 3u);

  writeText(tmp / "d", "FoamFile { format ascii; class scalarField; object d; }\n5{0}\n");
  EXPECT_EQ(readFieldInfo(tmp / "d").size, 5u);
  writeText(tmp / "d",
            "FoamFile { format ascii; class scalarField; }\n(1 2)\n");  // unsized; no object
  info = readFieldInfo(tmp / "d");
  EXPECT_EQ(info.size, 2u);
  EXPECT_EQ(info.object, "d");
  writeText(tmp / "d", "FoamFile { format ascii; class scalarField; }\nuniform 1\n");
  EXPECT_TRUE(readFieldInfo(tmp / "d").uniform);
}

TEST(FieldFiles, ReadFieldInfoOfALargeFileWithALongHeader) {
  TempDir tmp;
  // A header comment longer than the first block read.
  std::string text =
      "/*" + std::string(70000, '-') + "*/\nFoamFile { format ascii; class scalarField; }\n";
  text += "3(1 2 3)\n";
  writeText(tmp / "d", text);
  EXPECT_EQ(readFieldInfo(tmp / "d").size, 3u);
  writeField(tmp / "big", std::vector<scalar>(100000, 0.5), {WriteFormat::binary, 6, ""});
  EXPECT_EQ(readFieldInfo(tmp / "big").size, 100000u);
}

TEST(FieldFiles, ListFields) {
  TempDir tmp;
  const auto cloud = tmp / "0.1/lagrangian/particles";
  std::filesystem::create_directories(cloud);
  writeField(cloud / "U", std::vector<Vec3>(2, Vec3::Zero()), {});
  writeField(cloud / "d", std::vector<scalar>(2, 1.0), {WriteFormat::binary, 6, ""});
  writeField(cloud / "origId", std::vector<label>{0, 1}, {});
  writeText(cloud / "notes.txt", "not a field\n");
  writeText(cloud / ".U.tmp.123.0", "FoamFile {}");  // a leftover temporary: hidden
  std::filesystem::create_directories(cloud / "sub");
  EXPECT_EQ(listFields(cloud), (std::vector<std::string>{"U", "d", "origId"}));
  EXPECT_TRUE(listFields(tmp / "missing").empty());
}

}  // namespace
}  // namespace isph
