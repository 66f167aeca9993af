// Hostile input: each of these crashed the parser, hung it or passed a value that is not a
// number (issue 34). Every one is now a FatalError naming the file, the line and the limit.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "DictionaryTestHelpers.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {
namespace {

using test::expectErrorAt;
using test::expectFatal;
using test::TempDir;

std::string repeat(const std::string& s, std::size_t n) {
  std::string out;
  out.reserve(s.size() * n);
  for (std::size_t i = 0; i < n; ++i) out += s;
  return out;
}

// 10,000 nested sub-dictionaries (30 KB) overflowed the stack: exit 139.
TEST(DictionaryLimits, DeepNestingIsRefusedNotACrash) {
  const std::string deep = repeat("a { ", 10000) + repeat("} ", 10000);
  expectErrorAt(expectFatal([&] { Dictionary::parse(deep, "deep"); }), "deep", 1,
                {"nested more than 100 levels"});
  // The limit is far above what a case nests: 100 levels read.
  const Dictionary ok = Dictionary::parse(repeat("a { ", 100) + "x 1;" + repeat("} ", 100), "ok");
  const Dictionary* d = &ok;
  for (int i = 0; i < 100; ++i) d = &d->subDict("a");
  EXPECT_EQ(d->get<int>("x"), 1);
}

TEST(DictionaryLimits, DeepBracketsInAValueAreRefused) {
  expectErrorAt(expectFatal([] {
                  Dictionary::parse("x\n" + repeat("(", 5000) + repeat(")", 5000) + ";", "d");
                }),
                "d", 2, {"brackets nested more than 100 levels", "'x'"});
}

// `$a` as a value copies a; a chain of them nests (and doubles) without a brace in the file.
TEST(DictionaryLimits, SubstitutionChainsAreRefused) {
  std::string nested = "a0 { x 1; }\n";
  for (int i = 1; i <= 200; ++i) nested += fmt::format("a{} {{ y $a{}; }}\n", i, i - 1);
  expectFatal([&] { Dictionary::parse(nested, "nested"); });

  std::string doubling = "b0 1;\n";
  for (int i = 1; i <= 40; ++i) doubling += fmt::format("b{} $b{} $b{};\n", i, i - 1, i - 1);
  const auto e = expectFatal([&] { Dictionary::parse(doubling, "doubling"); });
  EXPECT_NE(e.report().find("substitutions of this dictionary copy more than"), std::string::npos)
      << e.report();
  EXPECT_EQ(e.where().line, 23) << e.report();  // b22 would hold 2^22 tokens
}

TEST(DictionaryLimits, OverlongTokenIsRefused) {
  const std::string text = "a 1;\nb \"" + std::string(2 << 20, 'x');  // a string never closed
  expectErrorAt(expectFatal([&] { Dictionary::parse(text, "d"); }), "d", 2,
                {"longer than 1024 KiB"});
  expectErrorAt(expectFatal([] { Dictionary::parse("c " + std::string(2 << 20, 'y') + ";", "d"); }),
                "d", 1, {"longer than 1024 KiB"});
}

// `#include "/dev/zero"` read until the memory ran out.
TEST(DictionaryLimits, IncludeOfADeviceOrDirectoryIsRefused) {
  TempDir dir;
  const auto main = dir.write("dict", "a 1;\n#include \"/dev/zero\"\n");
  expectErrorAt(expectFatal([&] { Dictionary::readFile(main); }), main.string(), 2,
                {"#include \"/dev/zero\"", "a character device, not a regular file"});
  const auto sub =
      dir.write("dict2", "#includeIfPresent \"/dev/zero\"\n");  // present, but not a file
  expectFatal([&] { Dictionary::readFile(sub); });
  std::filesystem::create_directories(dir.path() / "folder");
  const auto folder = dir.write("dict3", "\n\n#include \"folder\"\n");
  expectErrorAt(expectFatal([&] { Dictionary::readFile(folder); }), folder.string(), 3,
                {"Is a directory"});
  const auto e = expectFatal([] { Dictionary::readFile("/dev/zero"); });
  EXPECT_NE(e.report().find("not a regular file"), std::string::npos) << e.report();
}

// Found by fuzzing: a NUL byte ended a word without being one, and the lexer made empty words
// at the same place until memory ran out (tests/fuzz/regressions/dictionary/).
TEST(DictionaryLimits, ANulByteIsAnErrorNotAHang) {
  const std::string text = std::string("a 1;\nclass dic") + '\0' + "t;\n";
  expectErrorAt(expectFatal([&] { Dictionary::parse(text, "d"); }), "d", 2, {"a NUL byte"});
}

// Found by fuzzing: a list size beyond a long was cast to one (undefined behaviour), and a
// uniform list 1000000000{1} asked for 8 GB.
TEST(DictionaryLimits, HugeListSizesAreRefused) {
  const auto d = Dictionary::parse("a 9000000000000000000000000000000000000000000(1);\nb 1000000000{1};\n", "d");
  expectErrorAt(expectFatal([&] { d.get<std::vector<double>>("a"); }), "d", 1, {"more than the 16777216"});
  expectErrorAt(expectFatal([&] { d.get<std::vector<double>>("b"); }), "d", 2, {"a list of 1000000000 elements"});
}

// "did you mean" compared a 1 MiB name with every keyword by edit distance (length squared
// each): an undefined $<long name> in a large dictionary would not finish. Now it is refused
// at once, without a suggestion.
TEST(DictionaryLimits, AnUndefinedLongVariableIsRefusedAtOnce) {
  std::string text;
  for (int i = 0; i < 1000; ++i) text += fmt::format("{} {};\n", std::string(1000, 'k') + std::to_string(i), i);
  text += "x $" + std::string(1000003, 'k') + ";\n";
  const auto e = expectFatal([&] { Dictionary::parse(text, "d"); });
  EXPECT_NE(e.report().find("undefined variable"), std::string::npos);
  EXPECT_EQ(e.report().find("did you mean"), std::string::npos);
}

TEST(DictionaryLimits, FileBeyondTheSizeLimitIsRefused) {
  TempDir dir;
  const auto big = dir.path() / "big";
  std::ofstream(big) << "a 1;\n";
  std::filesystem::resize_file(big, (std::size_t{300} << 20));  // sparse: no disk used
  const auto e = expectFatal([&] { Dictionary::readFile(big); });
  EXPECT_NE(e.report().find("holds 300 MiB, more than the 256 MiB"), std::string::npos)
      << e.report();
}

// nan, inf and 1e400 were words, and then "expected a number, found word 'nan'" (or passed
// through a field reader unnoticed): now they are named for what they are.
TEST(DictionaryLimits, NonFiniteNumbersAreNamed) {
  const auto d = Dictionary::parse(
      "a nan;\nb -inf;\nc 1e400;\nd (0 NaN 0);\ne [0 1 inf 0 0 0 0] 2;\nf Infinity;\ng 1e-400;\nl "
      "(1 2 inf);\n"
      "n nan;\n",
      "constant/g");
  expectErrorAt(expectFatal([&] { d.get<double>("a"); }), "constant/g", 1,
                {"'nan' is not a finite number", "keyword 'a'"});
  expectErrorAt(expectFatal([&] { d.get<double>("b"); }), "constant/g", 2,
                {"'-inf' is not a finite number"});
  expectErrorAt(expectFatal([&] { d.get<double>("c"); }), "constant/g", 3,
                {"'1e400' is not a finite number"});
  expectErrorAt(expectFatal([&] { d.get<Vec3>("d"); }), "constant/g", 4,
                {"'NaN' is not a finite number"});
  expectErrorAt(expectFatal([&] { d.getDimensions("e"); }), "constant/g", 5,
                {"'inf' is not a finite number"});
  expectErrorAt(expectFatal([&] { d.get<double>("f"); }), "constant/g", 6,
                {"'Infinity' is not a finite number"});
  EXPECT_EQ(d.get<double>("g"),
            0.0);  // too small for a double: the nearest one, as strtod reads it
  expectErrorAt(expectFatal([&] { d.get<std::vector<double>>("l"); }), "constant/g", 8,
                {"'inf' is not a finite number"});
  expectErrorAt(expectFatal([&] { d.get<int>("n"); }), "constant/g", 9,
                {"'nan' is not a finite number"});
  EXPECT_EQ(d.get<std::string>("n"), "nan");  // a word where a word is wanted
}

// Each insert scanned every entry: 2 MB of distinct entries took 15 s, 50 MB hours. With the
// index, a million entries (14 MB) parse in about a second on the CI machine (measured 1.0 s;
// 50 MB in 4.3 s); the quadratic scan would take about an hour. The bound is not a speed
// claim but a guard against the quadratic scan coming back, 30 times the measured time.
TEST(DictionaryLimits, ManyDistinctEntriesParseInLinearTime) {
  constexpr int n = 1000000;
  std::string text;
  text.reserve(14 * n);
  for (int i = 0; i < n; ++i) text += fmt::format("key{} {};\n", i, i);
  const auto start = std::chrono::steady_clock::now();
  const Dictionary d = Dictionary::parse(text, "big");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(d.size(), static_cast<std::size_t>(n));
  EXPECT_EQ(d.get<int>("key999999"), 999999);
  EXPECT_EQ(d.entries()[123456].key(), "key123456");  // still in file order
  EXPECT_LT(seconds, 30.0);
}

TEST(DictionaryLimits, RemoveKeepsTheIndexInStep) {
  Dictionary d = Dictionary::parse("a 1; b 2; c 3; d 4;", "d");
  EXPECT_TRUE(d.remove("b"));
  EXPECT_FALSE(d.remove("b"));
  EXPECT_EQ(d.get<int>("c"), 3);
  EXPECT_EQ(d.get<int>("d"), 4);
  d.set("b", 5);
  EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "c", "d", "b"}));
  EXPECT_EQ(d.get<int>("b"), 5);
}

// A data file read as a dictionary by mistake: 20 warnings and a count, not a million lines.
TEST(DictionaryLimits, UnknownKeywordWarningsAreCapped) {
  std::string text;
  for (int i = 0; i < 1000; ++i) text += fmt::format("unknown{} 1;\n", i);
  const Dictionary d = Dictionary::parse(text, "d");
  const int before = warningCount();
  testing::internal::CaptureStderr();
  d.checkKeywords();
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_EQ(warningCount() - before, 21);
  EXPECT_NE(err.find("980 more unknown keywords in dictionary d are ignored"), std::string::npos)
      << err;
}

}  // namespace
}  // namespace isph
