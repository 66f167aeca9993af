// The parser and typed access on valid input: every construct of OpenFOAM dictionary syntax.
#include "core/dictionary/Dictionary.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "DictionaryTestHelpers.hpp"

namespace isph {
namespace {

using test::TempDir;

TEST(Dictionary, ScalarsIntegersWordsStringsAndSwitches) {
  const auto d = Dictionary::parse(R"(
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application   isphLandslideFoam;
endTime       2.5;
deltaT        1e-4;
small         -3.5E-2;
writeInterval 100;
title         "a quoted string";
on1 on; off1 off; yes1 yes; no1 no; true1 true; false1 false;
)",
                                   "controlDict");
  EXPECT_EQ(d.get<std::string>("application"), "isphLandslideFoam");
  EXPECT_DOUBLE_EQ(d.get<double>("endTime"), 2.5);
  EXPECT_DOUBLE_EQ(d.get<double>("deltaT"), 1e-4);
  EXPECT_DOUBLE_EQ(d.get<double>("small"), -3.5e-2);
  EXPECT_EQ(d.get<int>("writeInterval"), 100);
  EXPECT_DOUBLE_EQ(d.get<double>("writeInterval"), 100.0);  // an integer is a valid scalar
  EXPECT_EQ(d.get<std::string>("title"), "a quoted string");
  EXPECT_TRUE(d.get<bool>("on1"));
  EXPECT_FALSE(d.get<bool>("off1"));
  EXPECT_TRUE(d.get<bool>("yes1"));
  EXPECT_FALSE(d.get<bool>("no1"));
  EXPECT_TRUE(d.get<bool>("true1"));
  EXPECT_FALSE(d.get<bool>("false1"));
  EXPECT_TRUE(d.isDict("FoamFile"));
  EXPECT_EQ(d.subDict("FoamFile").get<std::string>("object"), "controlDict");
}

TEST(Dictionary, SubDictionariesKeepOrderAndNames) {
  const auto d = Dictionary::parse("outer { inner { a 1; } b 2; } c 3;", "dict");
  EXPECT_EQ(d.keys(), (std::vector<std::string>{"outer", "c"}));
  const Dictionary& inner = d.subDict("outer").subDict("inner");
  EXPECT_EQ(inner.get<int>("a"), 1);
  EXPECT_EQ(inner.name(), "dict/outer/inner");
  EXPECT_EQ(d.findDict("missing"), nullptr);
  EXPECT_EQ(d.subDictOrEmpty("missing").size(), 0u);
}

TEST(Dictionary, VectorsListsSizedListsNestedListsAndUniformLists) {
  const auto d = Dictionary::parse(R"(
g        (0 -9.81 0);
points   ((0 0 0) (1 0 0) (1 1 0));
sized    3(1 2 3);
uniform  4{0.5};
nested   ((1 2) (3) ());
words    (U p);
tensor   (1 2 3 4 5 6);
)",
                                   "dict");
  const Vec3 g = d.get<Vec3>("g");
  EXPECT_DOUBLE_EQ(g.y(), -9.81);
  const auto points = d.get<std::vector<Vec3>>("points");
  ASSERT_EQ(points.size(), 3u);
  EXPECT_DOUBLE_EQ(points[2].x(), 1.0);
  EXPECT_EQ(d.get<std::vector<int>>("sized"), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(d.get<std::vector<double>>("uniform"), (std::vector<double>(4, 0.5)));
  const auto nested = d.get<std::vector<std::vector<int>>>("nested");
  ASSERT_EQ(nested.size(), 3u);
  EXPECT_EQ(nested[0], (std::vector<int>{1, 2}));
  EXPECT_TRUE(nested[2].empty());
  EXPECT_EQ(d.get<std::vector<std::string>>("words"), (std::vector<std::string>{"U", "p"}));
  EXPECT_DOUBLE_EQ(d.get<SymmTensor>("tensor")[5], 6.0);
}

TEST(Dictionary, DimensionSetsAreAcceptedWhereOpenFOAMWritesThem) {
  const auto d = Dictionary::parse(R"(
dimensions [0 1 -2 0 0 0 0];
value      (0 -9.81 0);
nu         [0 2 -1 0 0 0 0] 1e-6;
rho        rho [1 -3 0 0 0] 1000;
)",
                                   "constant/g");
  EXPECT_DOUBLE_EQ(d.get<Vec3>("value").y(), -9.81);
  EXPECT_DOUBLE_EQ(d.get<double>("nu"), 1e-6);
  EXPECT_DOUBLE_EQ(d.get<double>("rho"), 1000);
  const auto dims = d.getDimensions("dimensions");
  ASSERT_TRUE(dims.has_value());
  EXPECT_EQ(dims->exponents[1], 1);
  EXPECT_EQ(dims->exponents[2], -2);
  EXPECT_EQ(d.getDimensions("rho")->exponents[0], 1);
  EXPECT_FALSE(d.getDimensions("value").has_value());
}

TEST(Dictionary, VariableSubstitutionWithScoping) {
  const auto d = Dictionary::parse(R"(
rho      1379;
spacing  0.0036;
sand     { rho $rho; phi 44; inner { deep 7; } }
copy     $sand;
phiCopy  $sand/phi;
phiDot   $sand.phi;
deepDot  $sand.inner.deep;
top      { rho 1; ref $:sand.phi; local $rho; parent { x $..rho; y $../rho; } }
braced   ${spacing};
list     ($rho $spacing);
merged   { $sand; phi 30; }
)",
                                   "dict");
  EXPECT_DOUBLE_EQ(d.subDict("sand").get<double>("rho"), 1379);
  EXPECT_DOUBLE_EQ(d.subDict("copy").get<double>("phi"), 44);
  EXPECT_DOUBLE_EQ(d.get<double>("phiCopy"), 44);
  EXPECT_DOUBLE_EQ(d.get<double>("phiDot"), 44);
  EXPECT_EQ(d.get<int>("deepDot"), 7);
  const Dictionary& top = d.subDict("top");
  EXPECT_DOUBLE_EQ(top.get<double>("ref"), 44);      // $: is the top level
  EXPECT_DOUBLE_EQ(top.get<double>("local"), 1);     // innermost scope first
  EXPECT_DOUBLE_EQ(top.subDict("parent").get<double>("x"), 1);  // $.. is the parent (top)
  EXPECT_DOUBLE_EQ(top.subDict("parent").get<double>("y"), 1);
  EXPECT_DOUBLE_EQ(d.get<double>("braced"), 0.0036);
  EXPECT_EQ(d.get<std::vector<double>>("list"), (std::vector<double>{1379, 0.0036}));
  EXPECT_DOUBLE_EQ(d.subDict("merged").get<double>("phi"), 30);  // later entries override
  EXPECT_DOUBLE_EQ(d.subDict("merged").get<double>("rho"), 1379);
}

TEST(Dictionary, IncludeIsRelativeToTheIncludingFile) {
  TempDir dir;
  dir.write("case/system/common/materials", "rho 2650;\nphi 35;\n");
  dir.write("case/system/common/more", "#include \"materials\"\nextra 1;\n");
  const auto main = dir.write("case/system/dict", "#include \"common/more\"\nphi 44;\nrhoCopy $rho;\n");
  const auto d = Dictionary::readFile(main);
  EXPECT_DOUBLE_EQ(d.get<double>("rho"), 2650);
  EXPECT_DOUBLE_EQ(d.get<double>("phi"), 44);  // the later entry wins
  EXPECT_EQ(d.get<int>("extra"), 1);
  EXPECT_DOUBLE_EQ(d.get<double>("rhoCopy"), 2650);
}

TEST(Dictionary, IncludeEtcReadsFromTheEtcFolder) {
  TempDir dir;
  dir.write("etc/caseDicts/defaults", "maxCo 0.25;\n");
  const auto main = dir.write("case/dict", "#includeEtc \"caseDicts/defaults\"\n");
  ::setenv("ISPH_ETC", (dir.path() / "etc").c_str(), 1);
  const auto d = Dictionary::readFile(main);
  ::unsetenv("ISPH_ETC");
  EXPECT_DOUBLE_EQ(d.get<double>("maxCo"), 0.25);
}

TEST(Dictionary, ProjectEtcCaseDictsAreIncludable) {
  // The shipped etc/caseDicts are part of the user contract: they must parse, and
  // entries after the #includeEtc override them.
  const auto d = Dictionary::parse(
      "p { #includeEtc \"caseDicts/solvers/pBoomerAMG\"\n tolerance 1e-6; }", "system/isphSolution");
  EXPECT_EQ(d.subDict("p").get<std::string>("solver"), "PCG");
  EXPECT_EQ(d.subDict("p").get<std::string>("preconditioner"), "BoomerAMG");
  EXPECT_DOUBLE_EQ(d.subDict("p").get<double>("tolerance"), 1e-6);
}

TEST(Dictionary, IncludeIfPresentAndRemove) {
  TempDir dir;
  const auto main = dir.write("dict", "#includeIfPresent \"nothere\"\na 1; b 2; c 3;\n#remove b\n#remove (c)\n");
  const auto d = Dictionary::readFile(main);
  EXPECT_EQ(d.keys(), (std::vector<std::string>{"a"}));
}

TEST(Dictionary, DefaultsAreReturnedAndEchoedOnce) {
  const auto d = Dictionary::parse("a 1;", "echoDict");
  testing::internal::CaptureStdout();
  EXPECT_DOUBLE_EQ(d.getOrDefault("maxCo", 0.2), 0.2);
  EXPECT_DOUBLE_EQ(d.getOrDefault("maxCo", 0.2), 0.2);
  EXPECT_EQ(d.getOrDefault("a", 5), 1);
  EXPECT_EQ(d.getOrDefault("kernel", "WendlandC2"), "WendlandC2");
  const std::string out = testing::internal::GetCapturedStdout();
  EXPECT_NE(out.find("maxCo 0.2;"), std::string::npos) << out;
  EXPECT_EQ(out.find("maxCo"), out.rfind("maxCo")) << "echoed twice:\n" << out;
  EXPECT_EQ(out.find(" a "), std::string::npos) << "a given value is not a default:\n" << out;
  EXPECT_NE(out.find("kernel WendlandC2;"), std::string::npos) << out;
}

TEST(Dictionary, ChoicesAndOptionalValues) {
  const auto d = Dictionary::parse("writeControl adjustableRunTime;", "dict");
  EXPECT_EQ(d.getChoice("writeControl", {"timeStep", "runTime", "adjustableRunTime"}), "adjustableRunTime");
  EXPECT_EQ(d.getChoiceOrDefault("stopAt", {"endTime", "writeNow"}, "endTime"), "endTime");
  EXPECT_FALSE(d.getOptional<double>("missing").has_value());
}

TEST(Dictionary, WriteThenParseRoundTrips) {
  Dictionary d("out");
  d.set("value", 0.1);
  d.set("name", std::string("0.1"));
  d.set("index", 42);
  d.set("g", Vec3(0, -9.81, 0));
  d.set("list", std::vector<double>{1, 2.5});
  d.set("text", std::string("two words"));
  d.subDictOrAdd("sub").set("flag", true);
  const auto back = Dictionary::parse(d.write(), "roundTrip");
  EXPECT_DOUBLE_EQ(back.get<double>("value"), 0.1);
  EXPECT_EQ(back.get<std::string>("name"), "0.1");
  EXPECT_EQ(back.get<int>("index"), 42);
  EXPECT_DOUBLE_EQ(back.get<Vec3>("g").y(), -9.81);
  EXPECT_EQ(back.get<std::vector<double>>("list"), (std::vector<double>{1, 2.5}));
  EXPECT_EQ(back.get<std::string>("text"), "two words");
  EXPECT_TRUE(back.subDict("sub").get<bool>("flag"));
}

// A misspelt keyword would leave the default in force (maxCO: the run used maxCo 1): an error.
TEST(Dictionary, MisspeltKeywordIsAnErrorWithTheNearestValidKeyword) {
  const auto d = Dictionary::parse("endTim 2;\nwriteInterval 1;\napplication x;\n", "system/controlDict");
  (void)d.getOrDefault("endTime", 1.0);
  (void)d.get<int>("writeInterval");
  test::expectErrorAt(test::expectFatal([&] { d.checkKeywords({"application"}); }), "system/controlDict", 1,
                      {"unknown keyword 'endTim'", "did you mean endTime?"});
  const auto c = Dictionary::parse("maxCo 0.5;\nmaxCO 0.2;\n", "system/controlDict");
  (void)c.getOrDefault("maxCo", 1.0);
  test::expectErrorAt(test::expectFatal([&] { c.checkKeywords(); }), "system/controlDict", 2,
                      {"'maxCO'", "did you mean maxCo?"});
}

// Three edits or more from every keyword read: a warning, the run goes on.
TEST(Dictionary, UnknownKeywordFarFromEveryKeywordWarns) {
  const auto d = Dictionary::parse("endTime 2;\nnotes none;\n", "system/controlDict");
  (void)d.get<double>("endTime");
  const int before = warningCount();
  testing::internal::CaptureStderr();
  d.checkKeywords();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(warningCount(), before + 1);
  EXPECT_NE(err.find("unknown keyword 'notes'"), std::string::npos) << err;
  EXPECT_NE(err.find("system/controlDict, line 2"), std::string::npos) << err;
}

// A name used as a $variable is the user's own, however close to a keyword: no error, no warning.
TEST(Dictionary, NameUsedAsVariableIsAllowed) {
  const auto d = Dictionary::parse("maxCo0 0.3;\nmaxCo $maxCo0;\nsub { rhoo 2; rho $rhoo; }\n", "system/controlDict");
  EXPECT_DOUBLE_EQ(d.getOrDefault("maxCo", 1.0), 0.3);
  EXPECT_DOUBLE_EQ(d.subDict("sub").get<double>("rho"), 2.0);
  const int before = warningCount();
  d.checkKeywords();
  d.subDict("sub").checkKeywords();
  EXPECT_EQ(warningCount(), before);
}

TEST(Dictionary, KeyGivenTwiceIsAnError) {
  test::expectErrorAt(test::expectFatal([] { Dictionary::parse("a 1;\nb 2;\na 3;\n", "d"); }), "d", 3,
                      {"keyword 'a' is given twice", "first at line 1"});
  test::expectErrorAt(test::expectFatal([] { Dictionary::parse("s\n{\n  x 1;\n  x 1;\n}\n", "d"); }), "d", 4,
                      {"'x' is given twice", "dictionary d/s"});
  test::expectErrorAt(test::expectFatal([] { Dictionary::parse("s { x 1; }\ns { y 1; }\n", "d"); }), "d", 2,
                      {"'s' is given twice"});
}

// What an #include or a $ expansion brings in may be overridden (the tutorials include
// etc/caseDicts/schemes/granular and change an entry); #remove then a new entry is no duplicate.
TEST(Dictionary, OverridingAnIncludedOrExpandedEntryIsAllowed) {
  test::TempDir dir;
  dir.write("defaults", "a 1;\nb 2;\n");
  const auto main = dir.write("dict", "#include \"defaults\"\na 3;\nbase { c 1; }\nsub { $base; c 2; }\n"
                                      "d 1;\n#remove d\nd 2;\n");
  const auto d = Dictionary::readFile(main);
  EXPECT_EQ(d.get<int>("a"), 3);
  EXPECT_EQ(d.get<int>("b"), 2);
  EXPECT_EQ(d.subDict("sub").get<int>("c"), 2);
  EXPECT_EQ(d.get<int>("d"), 2);
}

}  // namespace
}  // namespace isph
