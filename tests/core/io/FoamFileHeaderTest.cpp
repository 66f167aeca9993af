// The FoamFile header: OpenFOAM's layout, parseable by our dictionary reader.
#include <gtest/gtest.h>

#include <sstream>

#include "core/dictionary/Dictionary.hpp"
#include "core/io/FoamFileHeader.hpp"

namespace isph {
namespace {

TEST(FoamFileHeader, ParsesBackWithAllEntries) {
  const std::string text = foamFileHeader("vectorField", "U", "0.1/lagrangian/particles", false);
  std::size_t end = 0;
  const Dictionary top = Dictionary::parseHeader(text, "U", end);
  const Dictionary& h = top.subDict("FoamFile");
  EXPECT_EQ(h.get<double>("version"), 2.0);
  EXPECT_EQ(h.get<std::string>("format"), "ascii");
  EXPECT_EQ(h.get<std::string>("arch"), "LSB;label=32;scalar=64");
  EXPECT_EQ(h.get<std::string>("class"), "vectorField");
  EXPECT_EQ(h.get<std::string>("location"), "0.1/lagrangian/particles");
  EXPECT_EQ(h.get<std::string>("object"), "U");
  // After the header: the separator line and a blank line.
  EXPECT_EQ(
      text.substr(end),
      "\n// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n");
}

TEST(FoamFileHeader, BinaryAndNoLocation) {
  const std::string text = foamFileHeader("scalarField", "d", "", true);
  EXPECT_NE(text.find("    format      binary;\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("location"), std::string::npos) << text;
}

TEST(FoamFileHeader, OpenFoamLayout) {
  const std::string text = foamFileHeader("labelField", "origId", "0/lagrangian/particles", false);
  EXPECT_EQ(text.rfind("/*---", 0), 0u);
  EXPECT_NE(text.find("isphLandslide"), std::string::npos);
  EXPECT_EQ(text.find("OpenFOAM"), std::string::npos);
  EXPECT_NE(text.find("\nFoamFile\n{\n    version     2.0;\n    format      ascii;\n"
                      "    arch        \"LSB;label=32;scalar=64\";\n    class       labelField;\n"
                      "    location    \"0/lagrangian/particles\";\n    object      origId;\n}\n"),
            std::string::npos)
      << text;
  // The banner is 79 columns wide, as OpenFOAM's.
  std::istringstream lines(text);
  std::string line;
  for (int i = 0; i < 4 && std::getline(lines, line); ++i) EXPECT_EQ(line.size(), 79u) << line;
}

TEST(FoamFileHeader, Footer) {
  EXPECT_EQ(
      foamFileFooter(),
      "\n\n// ************************************************************************* //\n");
  EXPECT_EQ(foamFileArch(), "LSB;label=32;scalar=64");
}

}  // namespace
}  // namespace isph
