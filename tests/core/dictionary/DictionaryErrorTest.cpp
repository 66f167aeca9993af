// Bad input: every error names the file and the line (and the keyword) and says what
// was expected.
#include <gtest/gtest.h>

#include "DictionaryTestHelpers.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {
namespace {

using test::expectErrorAt;
using test::expectFatal;
using test::TempDir;

TEST(DictionaryErrors, MissingSemicolonBeforeTheNextKeyword) {
  const auto e = expectFatal([] { Dictionary::parse("endTime 2.5\ndeltaT 1e-4;\n", "system/controlDict"); });
  expectErrorAt(e, "system/controlDict", 1, {"missing ';'", "endTime"});
}

TEST(DictionaryErrors, MissingSemicolonAtEndOfFile) {
  const auto e = expectFatal([] { Dictionary::parse("a 1;\nb 2", "dict"); });
  expectErrorAt(e, "dict", 2, {"missing ';'", "'b'"});
}

TEST(DictionaryErrors, MissingSemicolonBeforeClosingBrace) {
  const auto e = expectFatal([] { Dictionary::parse("sub\n{\n    a 1\n}\n", "dict"); });
  expectErrorAt(e, "dict", 3, {"missing ';'", "'a'"});
}

TEST(DictionaryErrors, UnclosedBrace) {
  const auto e = expectFatal([] { Dictionary::parse("a 1;\nsand\n{\n  rho 1;\n", "constant/materialProperties"); });
  expectErrorAt(e, "constant/materialProperties", 3, {"not closed", "'}'", "sand"});
}

TEST(DictionaryErrors, UnclosedList) {
  const auto e = expectFatal([] { Dictionary::parse("points\n(\n (0 0 0)\n", "system/particleMeshDict"); });
  expectErrorAt(e, "system/particleMeshDict", 2, {"not closed", "points"});
}

TEST(DictionaryErrors, MismatchedBracket) {
  const auto e = expectFatal([] { Dictionary::parse("g (0 -9.81 0];\n", "constant/g"); });
  expectErrorAt(e, "constant/g", 1, {"does not match"});
}

TEST(DictionaryErrors, UnexpectedClosingBrace) {
  const auto e = expectFatal([] { Dictionary::parse("a 1;\n}\n", "dict"); });
  expectErrorAt(e, "dict", 2, {"unexpected '}'"});
}

TEST(DictionaryErrors, WrongTypeNamesKeywordAndExpectation) {
  const auto d = Dictionary::parse("FoamFile {}\nendTime  soon;\ng (0 -9.81);\nflag maybe;\nn 2.5;\n", "ctrl");
  expectErrorAt(expectFatal([&] { d.get<double>("endTime"); }), "ctrl", 2,
                {"keyword 'endTime'", "expected a number", "word 'soon'"});
  expectErrorAt(expectFatal([&] { d.get<Vec3>("g"); }), "ctrl", 3, {"keyword 'g'", "vector (x y z)"});
  expectErrorAt(expectFatal([&] { d.get<bool>("flag"); }), "ctrl", 4, {"on/off"});
  expectErrorAt(expectFatal([&] { d.get<int>("n"); }), "ctrl", 5, {"an integer", "2.5"});
}

TEST(DictionaryErrors, TrailingTokensAfterAValue) {
  const auto d = Dictionary::parse("endTime 2.5 3;\n", "ctrl");
  expectErrorAt(expectFatal([&] { d.get<double>("endTime"); }), "ctrl", 1, {"unexpected number 3"});
}

TEST(DictionaryErrors, MissingRequiredKeywordNamesDictionaryAndSuggests) {
  const auto d = Dictionary::parse("endTim 2.5;\n", "system/controlDict");
  const auto e = expectFatal([&] { d.get<double>("endTime"); });
  EXPECT_EQ(*e.where().file, "system/controlDict");
  const std::string r = e.report();
  EXPECT_NE(r.find("keyword 'endTime' is undefined"), std::string::npos) << r;
  EXPECT_NE(r.find("did you mean endTim?"), std::string::npos) << r;
  EXPECT_NE(r.find("expected: endTime a number;"), std::string::npos) << r;
}

TEST(DictionaryErrors, MissingKeywordInSubDictionaryNamesItsLine) {
  const auto d = Dictionary::parse("a 1;\nmaterials\n{\n  sand { phi 44; }\n}\n", "constant/materialProperties");
  const Dictionary& sand = d.subDict("materials").subDict("sand");
  const auto e = expectFatal([&] { sand.get<double>("rho"); });
  expectErrorAt(e, "constant/materialProperties", 4, {"'rho'", "materials/sand"});
}

TEST(DictionaryErrors, InvalidChoiceSuggestsNearest) {
  const auto d = Dictionary::parse("\nwriteControl adjustableRuntime;\n", "ctrl");
  const auto e = expectFatal([&] { d.getChoice("writeControl", {"timeStep", "runTime", "adjustableRunTime"}); });
  expectErrorAt(e, "ctrl", 2, {"timeStep|runTime|adjustableRunTime", "did you mean adjustableRunTime?"});
}

TEST(DictionaryErrors, UnknownIncludeFileNamesIncludingFileAndLine) {
  TempDir dir;
  const auto main = dir.write("dict", "a 1;\n#include \"missingFile\"\n");
  const auto e = expectFatal([&] { Dictionary::readFile(main); });
  expectErrorAt(e, main.string(), 2, {"cannot open the #include file \"missingFile\""});
}

TEST(DictionaryErrors, ErrorInsideIncludedFileNamesThatFile) {
  TempDir dir;
  const auto inc = dir.write("inc", "\n\nbad 1\nnext 2;\n");
  const auto main = dir.write("dict", "#include \"inc\"\n");
  const auto e = expectFatal([&] { Dictionary::readFile(main); });
  expectErrorAt(e, inc.string(), 3, {"missing ';'"});
}

TEST(DictionaryErrors, CircularIncludeIsCaught) {
  TempDir dir;
  const auto main = dir.write("dict", "#include \"dict\"\n");
  const auto e = expectFatal([&] { Dictionary::readFile(main); });
  EXPECT_NE(std::string(e.what()).find("nested more than"), std::string::npos) << e.report();
}

TEST(DictionaryErrors, UndefinedVariableAndUnknownDirective) {
  expectErrorAt(expectFatal([] { Dictionary::parse("rho 1;\nx $rh;\n", "dict"); }), "dict", 2,
                {"undefined variable '$rh'", "did you mean rho?"});
  expectErrorAt(expectFatal([] { Dictionary::parse("\n#inclde \"x\"\n", "dict"); }), "dict", 2,
                {"unknown directive '#inclde'", "did you mean include?"});
}

TEST(DictionaryErrors, ListSizeMismatch) {
  const auto d = Dictionary::parse("l 3(1 2);\n", "dict");
  expectErrorAt(expectFatal([&] { d.get<std::vector<int>>("l"); }), "dict", 1, {"3 elements but holds 2"});
}

TEST(DictionaryErrors, MissingFileIsAClearError) {
  const auto e = expectFatal([] { Dictionary::readFile("/nonexistent/system/controlDict"); });
  EXPECT_NE(std::string(e.what()).find("cannot open file /nonexistent/system/controlDict"), std::string::npos);
}

}  // namespace
}  // namespace isph
