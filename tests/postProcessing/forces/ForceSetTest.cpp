// The sets of system/sampleForcesDict: values, defaults and errors that name the file, line
// and keyword.
#include "postProcessing/forces/ForceSet.hpp"

#include <gtest/gtest.h>

#include "core/dictionary/Dictionary.hpp"

namespace isph {
namespace {

std::string errorOf(const std::string& text) {
  try {
    const Dictionary d = Dictionary::parse(text, "system/sampleForcesDict");
    readForceSets(d, {"cloud"});
  } catch (const FatalError& e) {
    return e.report();
  }
  return "";
}

TEST(ForceSet, ReadsEverySetWithItsDefaults) {
  const Dictionary d = Dictionary::parse(
      "cloud particles;\n"
      "barrier { patches (barrier); CofR (2.3 0 0); width 0.3; reference \"data/f.csv\"; referenceColumns (1 3); }\n"
      "walls { patches (left right); }\n"
      "face { patches (barrier); facing (-2 0 0); }\n",
      "system/sampleForcesDict");
  const auto sets = readForceSets(d, {"cloud"});
  ASSERT_EQ(sets.size(), 3u);
  EXPECT_FALSE(sets[0].facing.has_value());
  EXPECT_EQ(sets[2].facing.value_or(Vec3::Zero()), Vec3(-2, 0, 0));
  EXPECT_EQ(sets[0].name, "barrier");
  EXPECT_EQ(sets[0].patchNames, std::vector<std::string>{"barrier"});
  EXPECT_EQ(sets[0].CofR, Vec3(2.3, 0, 0));
  EXPECT_DOUBLE_EQ(sets[0].widthOrUnit(), 0.3);
  EXPECT_EQ(sets[0].reference.value_or(""), "data/f.csv");
  EXPECT_EQ(sets[0].referenceColumns[1], 3);
  EXPECT_EQ(sets[1].patchNames, (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(sets[1].CofR, Vec3::Zero());
  EXPECT_FALSE(sets[1].width.has_value());
  EXPECT_DOUBLE_EQ(sets[1].widthOrUnit(), 1.0);
}

TEST(ForceSet, ErrorsNameTheFileLineAndKeyword) {
  const std::string missing = errorOf("FoamFile { version 2.0; }\nbarrier\n{\n    CofR (0 0 0);\n}\n");
  EXPECT_NE(missing.find("'patches'"), std::string::npos) << missing;
  EXPECT_NE(missing.find("system/sampleForcesDict"), std::string::npos) << missing;

  const std::string width = errorOf("barrier\n{\n    patches (barrier);\n    width -1;\n}\n");
  EXPECT_NE(width.find("'width'"), std::string::npos) << width;
  EXPECT_NE(width.find("line 4"), std::string::npos) << width;

  const std::string facing = errorOf("barrier\n{\n    patches (barrier);\n    facing (0 0 0);\n}\n");
  EXPECT_NE(facing.find("'facing'"), std::string::npos) << facing;
  EXPECT_NE(facing.find("line 4"), std::string::npos) << facing;

  const std::string none = errorOf("cloud particles;\n");
  EXPECT_NE(none.find("names no set"), std::string::npos) << none;

  const std::string columns = errorOf("b { patches (b); referenceColumns (0 2); }\n");
  EXPECT_NE(columns.find("'referenceColumns'"), std::string::npos) << columns;
}

TEST(ForceSet, UnknownPatchListsTheCloudsPatches) {
  const Dictionary d = Dictionary::parse("barrier\n{\n    patches (barier);\n}\n", "system/sampleForcesDict");
  const auto sets = readForceSets(d);
  CloudProperties props;
  props.patches = {{"bed", 25}, {"barrier", 25}};
  try {
    patchLabels(sets[0], props);
    FAIL() << "an unknown patch was accepted";
  } catch (const FatalError& e) {
    const std::string r = e.report();
    EXPECT_NE(r.find("no patch 'barier'"), std::string::npos) << r;
    EXPECT_NE(r.find("(bed barrier)"), std::string::npos) << r;
    EXPECT_NE(r.find("line 3"), std::string::npos) << r;
  }
  const Dictionary ok = Dictionary::parse("s { patches (barrier bed); }", "x");
  EXPECT_EQ(patchLabels(readForceSets(ok)[0], props), (std::vector<label>{1, 0}));
}

}  // namespace
}  // namespace isph
