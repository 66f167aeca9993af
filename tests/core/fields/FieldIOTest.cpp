// Particle field files: round trips of every type in ascii and binary, OpenFOAM's layout,
// and the uniform forms accepted on read.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "../io/IoTestHelpers.hpp"
#include "core/fields/FieldIO.hpp"

namespace isph {
namespace {

using iotest::readText;
using iotest::TempDir;
using iotest::writeText;

// Random values over many magnitudes, with exact zeros, negatives and awkward decimals.
template <class T>
std::vector<T> sampleValues(std::size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-12, 12);
  auto number = [&] { return mantissa(rng) * std::pow(10.0, exponent(rng)); };
  std::vector<T> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    if constexpr (std::is_same_v<T, label>) {
      out[i] = static_cast<label>(rng() % 2000000) - 1000000;
    } else if constexpr (std::is_same_v<T, scalar>) {
      out[i] = number();
    } else {
      for (int k = 0; k < out[i].size(); ++k) out[i][k] = number();
    }
  }
  if (n > 2) {
    if constexpr (std::is_same_v<T, label>) {
      out[0] = 0;
      out[1] = std::numeric_limits<label>::max();
      out[2] = std::numeric_limits<label>::min();
    } else if constexpr (std::is_same_v<T, scalar>) {
      out[0] = 0.0;
      out[1] = 0.1;
      out[2] = -1.0 / 3.0;
    } else {
      out[0].setZero();
      out[1].setConstant(0.1);
    }
  }
  return out;
}

double component(double v, int) { return v; }
double component(label v, int) { return v; }
template <class V>
double component(const V& v, int k) {
  return v[k];
}
template <class T>
int nComponents() {
  if constexpr (std::is_same_v<T, scalar> || std::is_same_v<T, label>)
    return 1;
  else
    return T::RowsAtCompileTime;
}

// Every component equal within `relTol` (0: bit-exact).
template <class T>
void expectClose(const std::vector<T>& expected, const std::vector<T>& actual, double relTol) {
  ASSERT_EQ(expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    for (int k = 0; k < nComponents<T>(); ++k) {
      const double a = component(expected[i], k), b = component(actual[i], k);
      if (relTol == 0) {
        ASSERT_EQ(a, b) << "value " << i << " component " << k;
      } else {
        ASSERT_LE(std::abs(a - b), relTol * std::abs(a)) << "value " << i << " component " << k;
      }
    }
  }
}

template <class T>
class FieldRoundTrip : public ::testing::Test {};
using FieldTypes = ::testing::Types<scalar, label, Vec3, SymmTensor>;
TYPED_TEST_SUITE(FieldRoundTrip, FieldTypes);

TYPED_TEST(FieldRoundTrip, BinaryIsExact) {
  TempDir tmp;
  const auto values = sampleValues<TypeParam>(1000);
  writeField(tmp / "f", values, {WriteFormat::binary, 6, "0.1/lagrangian/particles"});
  expectClose(values, readField<TypeParam>(tmp / "f"), 0.0);
  expectClose(values, readField<TypeParam>(tmp / "f", values.size()), 0.0);
}

TYPED_TEST(FieldRoundTrip, AsciiToPrecision) {
  TempDir tmp;
  const auto values = sampleValues<TypeParam>(1000);
  for (int precision : {3, 6, 10}) {
    writeField(tmp / "f", values, {WriteFormat::ascii, precision, ""});
    // %.{p}g rounds to p significant digits: the relative error is at most half a unit in the
    // last digit, 0.5 * 10^(1-p) (for a leading digit 1), i.e. 5 * 10^-p.
    const double tol = std::is_same_v<TypeParam, label> ? 0.0 : 5.0 * std::pow(10.0, -precision);
    expectClose(values, readField<TypeParam>(tmp / "f"), tol);
  }
}

TYPED_TEST(FieldRoundTrip, AsciiAtPrecision17IsExact) {
  TempDir tmp;
  const auto values = sampleValues<TypeParam>(1000);
  writeField(tmp / "f", values, {WriteFormat::ascii, 17, ""});
  expectClose(values, readField<TypeParam>(tmp / "f"), 0.0);
}

TYPED_TEST(FieldRoundTrip, EmptyField) {
  TempDir tmp;
  for (auto format : {WriteFormat::ascii, WriteFormat::binary}) {
    writeField(tmp / "f", std::vector<TypeParam>{}, {format, 6, ""});
    EXPECT_TRUE(readField<TypeParam>(tmp / "f").empty());
    EXPECT_TRUE(readField<TypeParam>(tmp / "f", 0).empty());
  }
}

TYPED_TEST(FieldRoundTrip, ClassNameInHeader) {
  TempDir tmp;
  writeField(tmp / "f", sampleValues<TypeParam>(3), {});
  EXPECT_NE(readText(tmp / "f").find("class       " + fieldClassName<TypeParam>() + ";"),
            std::string::npos);
}

TEST(FieldIO, ClassNames) {
  EXPECT_EQ(fieldClassName<scalar>(), "scalarField");
  EXPECT_EQ(fieldClassName<label>(), "labelField");
  EXPECT_EQ(fieldClassName<Vec3>(), "vectorField");
  EXPECT_EQ(fieldClassName<SymmTensor>(), "symmTensorField");
}

TEST(FieldIO, AsciiLayoutIsOpenFoams) {
  TempDir tmp;
  writeField(tmp / "U", std::vector<Vec3>{Vec3(1, 2, 3), Vec3(0.5, -0.25, 1e-7)},
             {WriteFormat::ascii, 6, "0.1/lagrangian/particles"});
  const std::string text = readText(tmp / "U");
  EXPECT_NE(
      text.find("    class       vectorField;\n    location    \"0.1/lagrangian/particles\";\n"
                "    object      U;\n}\n"),
      std::string::npos)
      << text;
  EXPECT_NE(text.find("//\n\n\n2\n(\n(1 2 3)\n(0.5 -0.25 1e-07)\n)\n\n\n// *****"),
            std::string::npos)
      << text;

  writeField(tmp / "sigma", std::vector<SymmTensor>{(SymmTensor() << 1, 2, 3, 4, 5, 6).finished()},
             {});
  EXPECT_NE(readText(tmp / "sigma").find("\n1\n(\n(1 2 3 4 5 6)\n)\n"), std::string::npos);
  writeField(tmp / "origId", std::vector<label>{7, -3}, {});
  EXPECT_NE(readText(tmp / "origId").find("\n2\n(\n7\n-3\n)\n"), std::string::npos);
  writeField(tmp / "d", std::vector<scalar>{0.123456789}, {WriteFormat::ascii, 4, ""});
  EXPECT_NE(readText(tmp / "d").find("\n1\n(\n0.1235\n)\n"), std::string::npos);
}

TEST(FieldIO, BinaryLayoutIsOpenFoams) {
  TempDir tmp;
  const std::vector<scalar> values{1.5, -2.0};
  writeField(tmp / "d", values, {WriteFormat::binary, 6, ""});
  const std::string text = readText(tmp / "d");
  std::string raw(16, '\0');
  std::memcpy(raw.data(), values.data(), 16);
  EXPECT_NE(text.find("    format      binary;\n"), std::string::npos);
  EXPECT_NE(text.find("\n2\n(" + raw + ")\n"), std::string::npos);
}

TEST(FieldIO, WriteIsAtomicAndLeavesNoTemporary) {
  TempDir tmp;
  writeField(tmp / "d", std::vector<scalar>{1, 2}, {});
  writeField(tmp / "d", std::vector<scalar>{3}, {});
  EXPECT_EQ(readField<scalar>(tmp / "d"), std::vector<scalar>{3});
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(tmp.path())) ++n;
  EXPECT_EQ(n, 1);
}

// ---- forms accepted on read -------------------------------------------------------------

std::string header(const std::string& cls, const std::string& format = "ascii") {
  return "FoamFile\n{\n    version 2.0;\n    format " + format + ";\n    class " + cls +
         ";\n    object f;\n}\n// * * * //\n\n";
}

TEST(FieldIO, UniformListForm) {
  TempDir tmp;
  writeText(tmp / "d", header("scalarField") + "3{1.5}\n");
  EXPECT_EQ(readField<scalar>(tmp / "d"), (std::vector<scalar>{1.5, 1.5, 1.5}));
  EXPECT_EQ(readField<scalar>(tmp / "d", 3), (std::vector<scalar>{1.5, 1.5, 1.5}));
  writeText(tmp / "U", header("vectorField") + "2 { (1 2 3) }\n");
  EXPECT_EQ(readField<Vec3>(tmp / "U"), (std::vector<Vec3>{Vec3(1, 2, 3), Vec3(1, 2, 3)}));
}

TEST(FieldIO, UniformKeywordWithExpectedSize) {
  TempDir tmp;
  writeText(tmp / "U", header("vectorField") + "uniform (1 2 3)\n");
  EXPECT_EQ(readField<Vec3>(tmp / "U", 4), std::vector<Vec3>(4, Vec3(1, 2, 3)));
  writeText(tmp / "id", header("labelField") + "uniform -7\n");
  EXPECT_EQ(readField<label>(tmp / "id", 2), (std::vector<label>{-7, -7}));
  writeText(tmp / "d",
            header("scalarField", "binary") + "uniform 2.5\n");  // text even in binary files
  EXPECT_EQ(readField<scalar>(tmp / "d", 1), (std::vector<scalar>{2.5}));
}

TEST(FieldIO, OtherAsciiForms) {
  TempDir tmp;
  // One line, comments, a leading '+', an unsized list, no separator line.
  writeText(tmp / "d",
            "/* banner */\nFoamFile { version 2.0; format ascii; class scalarField; object d; }\n"
            "3(1 +2 /* two */ 3e0) // done\n");
  EXPECT_EQ(readField<scalar>(tmp / "d"), (std::vector<scalar>{1, 2, 3}));
  writeText(tmp / "d", header("scalarField") + "(4 5)\n");
  EXPECT_EQ(readField<scalar>(tmp / "d", 2), (std::vector<scalar>{4, 5}));
  writeText(tmp / "U", header("vectorField") + "1((1 2 3))");
  EXPECT_EQ(readField<Vec3>(tmp / "U"), (std::vector<Vec3>{Vec3(1, 2, 3)}));
}

TEST(FieldIO, EmptyBinaryListAsOpenFoamWritesIt) {
  TempDir tmp;
  writeText(tmp / "d", header("scalarField", "binary") + "\n0\n\n\n// *** //\n");
  EXPECT_TRUE(readField<scalar>(tmp / "d").empty());
  writeText(tmp / "d", header("scalarField", "binary") + "\n0()\n");
  EXPECT_TRUE(readField<scalar>(tmp / "d").empty());
}

TEST(FieldIO, LargeAsciiField) {
  TempDir tmp;
  const auto values = sampleValues<Vec3>(200000);
  writeField(tmp / "U", values, {WriteFormat::ascii, 17, ""});
  expectClose(values, readField<Vec3>(tmp / "U", values.size()), 0.0);
}

}  // namespace
}  // namespace isph
