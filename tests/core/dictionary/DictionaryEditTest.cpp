// isphDictionary -set: one entry's value changed in the file's text, comments and layout kept,
// the result parsed again; what cannot be set is an error and nothing changes.
#include "core/dictionary/DictionaryEdit.hpp"

#include <gtest/gtest.h>

#include "DictionaryTestHelpers.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {
namespace {

using test::expectFatal;

const std::string scene =
    "spacing         0.0036;     // the paper's\n"
    "walls\n"
    "{\n"
    "    bed\n"
    "    {\n"
    "        type polyline;\n"
    "        points ((0 0 0)\n"
    "                (2.9 0 0));\n"
    "        frictionAngle   25;   // delta\n"
    "    }\n"
    "    barrier { type box; min (2.3 0 0); max (2.32 0.3 0); frictionAngle 25; }\n"
    "}\n";

TEST(DictionaryEdit, ReplacesOnlyTheValue) {
  const std::string edited = setEntryValue(scene, "pm", {"walls", "bed", "frictionAngle"}, "20");
  EXPECT_NE(edited.find("        frictionAngle   20;   // delta\n"), std::string::npos) << edited;
  EXPECT_EQ(edited.size(), scene.size());  // nothing else changed
  const auto d = Dictionary::parse(edited, "pm");
  EXPECT_DOUBLE_EQ(d.subDict("walls").subDict("bed").get<double>("frictionAngle"), 20);
  EXPECT_DOUBLE_EQ(d.subDict("walls").subDict("barrier").get<double>("frictionAngle"), 25);
}

TEST(DictionaryEdit, ValuesOverSeveralLinesAndOnOneLine) {
  std::string edited = setEntryValue(scene, "pm", {"walls", "bed", "points"}, "((0 0 0) (1.8 0 0))");
  edited = setEntryValue(edited, "pm", {"walls", "barrier", "max"}, "(2.32 0.2 0)");
  edited = setEntryValue(edited, "pm", {"spacing"}, "0.0108");
  const auto d = Dictionary::parse(edited, "pm");
  EXPECT_EQ(d.subDict("walls").subDict("bed").get<std::vector<Vec3>>("points").back().x(), 1.8);
  EXPECT_DOUBLE_EQ(d.subDict("walls").subDict("barrier").get<Vec3>("max").y(), 0.2);
  EXPECT_DOUBLE_EQ(d.subDict("walls").subDict("barrier").get<Vec3>("min").x(), 2.3);
  EXPECT_DOUBLE_EQ(d.get<double>("spacing"), 0.0108);
  EXPECT_NE(edited.find("// the paper's"), std::string::npos);
}

TEST(DictionaryEdit, AddsAMissingTopLevelEntry) {
  const auto d = Dictionary::parse(setEntryValue(scene, "pm", {"maxParticles"}, "1e6"), "pm");
  EXPECT_DOUBLE_EQ(d.get<double>("maxParticles"), 1e6);
}

TEST(DictionaryEdit, RefusesWhatItCannotSet) {
  EXPECT_NE(expectFatal([] { setEntryValue(scene, "pm", {"walls", "bed"}, "1"); }).report().find("sub-dictionary"),
            std::string::npos);
  EXPECT_NE(expectFatal([] { setEntryValue(scene, "pm", {"walls", "gate", "frictionAngle"}, "1"); }).report().find(
                "keyword 'gate' is undefined"),
            std::string::npos);
  EXPECT_NE(expectFatal([] { setEntryValue(scene, "pm", {"walls", "bed", "typo"}, "1"); }).report().find(
                "no entry 'typo'"),
            std::string::npos);
  // a value that does not parse
  expectFatal([] { setEntryValue(scene, "pm", {"spacing"}, "(1 2"); });
}

TEST(DictionaryEdit, AnIncludedEntryIsSetInItsOwnFile) {
  test::TempDir dir;
  dir.write("common", "rho 1379;\n");
  const std::string text = "#include \"common\"\nphi 44;\n";
  const auto main = dir.write("materials", text);
  const auto e = expectFatal([&] { setEntryValue(text, main.string(), {"rho"}, "2000"); });
  EXPECT_NE(e.report().find("set it in that file"), std::string::npos) << e.report();
}

}  // namespace
}  // namespace isph
