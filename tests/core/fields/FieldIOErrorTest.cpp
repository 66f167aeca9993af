// Bad field files: every error names the file and the line and says what was expected.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "../io/IoTestHelpers.hpp"
#include "core/fields/FieldIO.hpp"

namespace isph {
namespace {

using iotest::contains;
using iotest::expectFatal;
using iotest::readText;
using iotest::TempDir;
using iotest::writeText;

namespace fs = std::filesystem;

// The error is located in `file` at `line` and its report contains every `part`.
void expectErrorAt(const FatalError& e, const fs::path& file, int line,
                   std::initializer_list<std::string> parts) {
  ASSERT_TRUE(e.where().file) << e.what();
  EXPECT_EQ(*e.where().file, file.string()) << e.report();
  EXPECT_EQ(e.where().line, line) << e.report();
  const std::string report = e.report();
  EXPECT_TRUE(contains(report, file.string() + ", line " + std::to_string(line))) << report;
  for (const auto& part : parts)
    EXPECT_TRUE(contains(report, part)) << "missing '" << part << "' in" << report;
}

// 1-based line of the first occurrence of `needle` in `file`.
int lineOf(const fs::path& file, const std::string& needle) {
  const std::string text = readText(file);
  const auto pos = text.find(needle);
  EXPECT_NE(pos, std::string::npos) << needle;
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n'));
}

void replaceInFile(const fs::path& file, const std::string& from, const std::string& to) {
  std::string text = readText(file);
  const auto pos = text.find(from);
  ASSERT_NE(pos, std::string::npos) << from;
  text.replace(pos, from.size(), to);
  writeText(file, text);
}

std::string header(const std::string& cls, const std::string& format = "ascii",
                   const std::string& arch = "") {
  return "FoamFile\n{\n    version 2.0;\n    format " + format + ";\n" +
         (arch.empty() ? "" : "    arch \"" + arch + "\";\n") + "    class " + cls +
         ";\n    object f;\n}\n// * * * //\n\n";
}

TEST(FieldIOErrors, BadAsciiTokenNamesFileLineAndExpectation) {
  TempDir tmp;
  const fs::path file = tmp / "U";
  writeField(file, std::vector<Vec3>{Vec3(1, 2, 3), Vec3(4, 5, 6), Vec3(7, 8, 9)}, {});
  replaceInFile(file, "(4 5 6)", "(4 abc 6)");
  const int line = lineOf(file, "(4 abc 6)");
  const auto e = expectFatal([&] { readField<Vec3>(file); });
  expectErrorAt(e, file, line, {"expected a vector (x y z)", "'abc'", "value 2 of 3"});
}

TEST(FieldIOErrors, BadScalarAndLabelTokens) {
  TempDir tmp;
  const fs::path d = tmp / "d";
  writeText(d, header("scalarField") + "3\n(\n1\n2x\n3\n)\n");
  expectErrorAt(expectFatal([&] { readField<scalar>(d); }), d, 13, {"expected a number", "'2x'"});
  const fs::path id = tmp / "id";
  writeText(id, header("labelField") + "2\n(\n1\n\n1.5\n)\n");
  expectErrorAt(expectFatal([&] { readField<label>(id); }), id, 14,
                {"expected a label (an integer)", "'1.5'"});
  writeText(id, header("labelField") + "1\n(\n3000000000\n)\n");
  expectErrorAt(expectFatal([&] { readField<label>(id); }), id, 12, {"out of range"});
}

// nan and inf passed both readers (issue 34): sampleForces then wrote -nan forces with exit 0
// and the solver failed later without naming a file.
TEST(FieldIOErrors, NonFiniteAsciiValuesNameFileAndLine) {
  TempDir tmp;
  const fs::path p = tmp / "p";
  for (const std::string bad : {"nan", "-inf", "inf", "Infinity", "1e400", "-1e999", "+nan"}) {
    writeText(p, header("scalarField") + "3\n(\n1\n" + bad + "\n3\n)\n");
    expectErrorAt(expectFatal([&] { readField<scalar>(p); }), p, 13,
                  {"'" + bad + "' is not a finite number", "value 2 of 3"});
  }
  const fs::path U = tmp / "U";
  writeText(U, header("vectorField") + "2\n(\n(0 0 0)\n(1 NAN 0)\n)\n");
  expectErrorAt(expectFatal([&] { readField<Vec3>(U); }), U, 13, {"'NAN' is not a finite number"});
  writeText(U, header("vectorField") + "uniform (0 inf 0)\n");
  expectErrorAt(expectFatal([&] { readField<Vec3>(U, 4); }), U, 10, {"'inf' is not a finite number"});
  writeText(U, header("vectorField") + "4{(0 0 nan)}\n");
  expectErrorAt(expectFatal([&] { readField<Vec3>(U); }), U, 10, {"'nan' is not a finite number"});
  // Too small for a double: the nearest one, as strtod reads it.
  writeText(p, header("scalarField") + "2(1e-400 -1e-330)\n");
  EXPECT_EQ(readField<scalar>(p), (std::vector<scalar>{0.0, -0.0}));
}

TEST(FieldIOErrors, NonFiniteBinaryValuesAreRefused) {
  TempDir tmp;
  const fs::path U = tmp / "U";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  writeField(U, std::vector<Vec3>{Vec3(1, 2, 3), Vec3(4, nan, 6)}, {WriteFormat::binary, 6, ""});
  const auto e = expectFatal([&] { readField<Vec3>(U); });
  EXPECT_EQ(*e.where().file, U.string());
  EXPECT_GT(e.where().line, 0);
  EXPECT_TRUE(contains(e.report(), "value 2 of 2 (component 2")) << e.report();
  EXPECT_TRUE(contains(e.report(), "is not a finite number (nan) in the binary data")) << e.report();
  const fs::path p = tmp / "p";
  writeField(p, std::vector<scalar>{1, std::numeric_limits<double>::infinity()}, {WriteFormat::binary, 6, ""});
  EXPECT_TRUE(contains(expectFatal([&] { readField<scalar>(p); }).report(), "(inf)"));
}

// Found by fuzzing (tests/fuzz/regressions/fieldBinary/): a positions-like read (no particle
// count known) of "999999943{0}" allocated 4 GB for 16 bytes of text. Refused above 2^24 values
// where the count is unknown; where it is known, N must equal it as before.
TEST(FieldIOErrors, HugeUniformListWithoutACountIsRefused) {
  TempDir tmp;
  const fs::path id = tmp / "origId";
  writeText(id, header("labelField", "binary", "LSB;label=32;scalar=64") + "999999943{0}\n");
  expectErrorAt(expectFatal([&] { readField<label>(id); }), id, 11,
                {"a uniform list N{value} of 999999943 values", "refused above 16777216 values"});
  writeText(id, header("labelField") + "16777217{7}\n");
  expectErrorAt(expectFatal([&] { readField<label>(id); }), id, 10, {"refused above 16777216 values"});
  writeText(id, header("labelField") + "16777216{7}\n");  // at the limit: read
  const auto values = readField<label>(id);
  EXPECT_EQ(values.size(), std::size_t{1} << 24);
  EXPECT_EQ(values.back(), 7);
  writeText(id, header("labelField") + "20000000{7}\n");  // the count known: its own check
  EXPECT_EQ(readField<label>(id, 20000000).size(), 20000000u);
  expectErrorAt(expectFatal([&] { readField<label>(id, 5); }), id, 10, {"holds 20000000 values but 5 were expected"});
}

TEST(FieldIOErrors, ClassMismatch) {
  TempDir tmp;
  const fs::path file = tmp / "d";
  writeField(file, std::vector<scalar>{1, 2}, {});
  const auto e = expectFatal([&] { readField<Vec3>(file); });
  expectErrorAt(e, file, lineOf(file, "class"), {"scalarField", "vectorField", "'d'"});
}

TEST(FieldIOErrors, SizeMismatch) {
  TempDir tmp;
  const fs::path file = tmp / "d";
  for (auto format : {WriteFormat::ascii, WriteFormat::binary}) {
    writeField(file, std::vector<scalar>{1, 2, 3}, {format, 6, ""});
    const auto e = expectFatal([&] { readField<scalar>(file, 5); });
    expectErrorAt(e, file, lineOf(file, "\n3\n") + 1, {"holds 3 values but 5 were expected"});
  }
  writeText(file, header("scalarField") + "3{1.5}\n");
  expectErrorAt(expectFatal([&] { readField<scalar>(file, 2); }), file, 10,
                {"holds 3 values but 2"});
}

TEST(FieldIOErrors, ListLengthDisagreesWithItsSize) {
  TempDir tmp;
  const fs::path file = tmp / "d";
  writeText(file, header("scalarField") + "3\n(\n1\n2\n)\n");
  expectErrorAt(expectFatal([&] { readField<scalar>(file); }), file, 14,
                {"ends after 2 values", "says 3"});
  writeText(file, header("scalarField") + "2\n(\n1\n2\n3\n)\n");
  expectErrorAt(expectFatal([&] { readField<scalar>(file); }), file, 14,
                {"expected ')' closing the list", "'3'"});
  writeText(file, header("scalarField") + "2\n(\n1\n");
  expectErrorAt(expectFatal([&] { readField<scalar>(file); }), file, 13, {"the end of the file"});
}

TEST(FieldIOErrors, UniformNeedsTheExpectedSize) {
  TempDir tmp;
  const fs::path file = tmp / "U";
  writeText(file, header("vectorField") + "uniform (1 2 3)\n");
  expectErrorAt(expectFatal([&] { readField<Vec3>(file); }), file, 10,
                {"'uniform'", "number of particles"});
  writeText(file, header("vectorField") + "uniform (1 2)\n");
  expectErrorAt(expectFatal([&] { readField<Vec3>(file, 3); }), file, 10,
                {"expected a vector (x y z)", "')'"});
}

TEST(FieldIOErrors, TruncatedBinaryFile) {
  TempDir tmp;
  const fs::path file = tmp / "U";
  std::vector<Vec3> values(100, Vec3(1, 2, 3));
  writeField(file, values, {WriteFormat::binary, 6, ""});
  const std::string full = readText(file);
  const auto open = full.find("\n100\n(") + 5;
  // Cut in the middle of the data, and just before the closing ')'.
  for (std::size_t keep : {open + 1 + 1000, open + 1 + 2400}) {
    writeText(file, full.substr(0, keep));
    const auto e = expectFatal([&] { readField<Vec3>(file); });
    expectErrorAt(e, file, lineOf(file, "\n100\n(") + 2, {"truncated", "2400 bytes"});
  }
  // Wrong byte after the data: the size or the data is corrupt.
  std::string corrupt = full;
  corrupt[open + 1 + 2400] = 'x';
  writeText(file, corrupt);
  EXPECT_TRUE(contains(expectFatal([&] { readField<Vec3>(file); }).what(),
                       "expected ')' after the 2400 bytes"));
  // A size larger than the file can hold.
  writeText(file, header("vectorField", "binary") + "\n1000000\n(abc)\n");
  EXPECT_TRUE(contains(expectFatal([&] { readField<Vec3>(file); }).what(), "truncated"));
  writeText(file, header("vectorField", "binary") + "\n1000000000000{(0 0 0)}\n");
  EXPECT_TRUE(contains(expectFatal([&] { readField<Vec3>(file); }).what(),
                       "beyond the largest particle count"));
}

TEST(FieldIOErrors, BinaryArchMismatchIsRefused) {
  TempDir tmp;
  const fs::path file = tmp / "id";
  writeText(file, header("labelField", "binary", "LSB;label=64;scalar=64") + "\n0\n");
  auto e = expectFatal([&] { readField<label>(file); });
  expectErrorAt(e, file, 5, {"label=64", "LSB;label=32;scalar=64"});
  writeText(file, header("labelField", "binary", "MSB;label=32;scalar=64") + "\n0\n");
  expectFatal([&] { readField<label>(file); });
  // Text is text: an ascii file from a 64-bit-label build reads fine.
  writeText(file, header("labelField", "ascii", "LSB;label=64;scalar=64") + "2(1 2)\n");
  EXPECT_EQ(readField<label>(file), (std::vector<label>{1, 2}));
}

TEST(FieldIOErrors, HeaderProblems) {
  TempDir tmp;
  const fs::path file = tmp / "d";
  writeText(file, "// no header\n\n3(1 2 3)\n");
  expectErrorAt(expectFatal([&] { readField<scalar>(file); }), file, 3,
                {"expected a FoamFile header"});
  writeText(file, "FoamFile\n{\n    format text;\n    class scalarField;\n}\n0()\n");
  expectErrorAt(expectFatal([&] { readField<scalar>(file); }), file, 3, {"format"});
  writeText(file, "FoamFile\n{\n    format ascii;\n}\n0()\n");
  EXPECT_TRUE(contains(expectFatal([&] { readField<scalar>(file); }).report(), "class"));
  writeText(file, header("scalarField") + "2(1 2) extra\n");
  expectErrorAt(expectFatal([&] { readField<scalar>(file); }), file, 10, {"unexpected 'extra'"});
  writeText(file, header("scalarField") + "many(1 2)\n");
  expectErrorAt(expectFatal([&] { readField<scalar>(file); }), file, 10,
                {"expected the number of values", "'many'"});
}

TEST(FieldIOErrors, MissingFileAndBadPrecision) {
  TempDir tmp;
  const auto e = expectFatal([&] { readField<scalar>(tmp / "nothing"); });
  EXPECT_TRUE(contains(e.what(), (tmp / "nothing").string())) << e.what();
  EXPECT_TRUE(contains(e.what(), "No such file or directory")) << e.what();
  expectFatal([&] { writeField(tmp / "d", std::vector<scalar>{1}, {WriteFormat::ascii, 0, ""}); });
  EXPECT_FALSE(fs::exists(tmp / "d"));
}

}  // namespace
}  // namespace isph
