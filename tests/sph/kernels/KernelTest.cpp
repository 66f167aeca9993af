// Kernels: unit integral (partition of unity), compact support, gradient consistent with W,
// lattice neighbour counts quoted in the numerics note, selection by name, the case's kernel.
#include "sph/kernels/Kernel.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "core/dictionary/Dictionary.hpp"

namespace isph {
namespace {

class KernelTest : public ::testing::TestWithParam<const char*> {};

// ∫ W dA over the plane, by the radial integral 2π ∫ W r dr (midpoint rule, 20k intervals).
double integral2D(const Kernel& k) {
  const int n = 20000;
  const double dr = k.supportRadius() / n;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) * dr;
    sum += k.W(r) * 2 * std::numbers::pi * r * dr;
  }
  return sum;
}

double integral3D(const Kernel& k) {
  const int n = 20000;
  const double dr = k.supportRadius() / n;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) * dr;
    sum += k.W(r) * 4 * std::numbers::pi * r * r * dr;
  }
  return sum;
}

TEST_P(KernelTest, IntegratesToOneIn2DAnd3D) {
  EXPECT_NEAR(integral2D(*makeKernel(GetParam(), 0.013, 2)), 1.0, 1e-6);
  EXPECT_NEAR(integral3D(*makeKernel(GetParam(), 0.013, 3)), 1.0, 1e-6);
}

TEST_P(KernelTest, CompactSupportAndMonotoneDecay) {
  const auto k = makeKernel(GetParam(), 0.5, 2);
  EXPECT_DOUBLE_EQ(k->supportRadius(), 1.0);
  EXPECT_EQ(k->W(1.0), 0.0);
  EXPECT_EQ(k->dWdr(1.2), 0.0);
  double previous = k->W(0);
  for (double r = 0.01; r < 1.0; r += 0.01) {
    EXPECT_LE(k->W(r), previous);
    EXPECT_LE(k->dWdr(r), 0.0);
    previous = k->W(r);
  }
}

TEST_P(KernelTest, DerivativeMatchesFiniteDifference) {
  const auto k = makeKernel(GetParam(), 0.1, 2);
  const double eps = 1e-7;
  for (double r = 0.005; r < 0.2; r += 0.0137) {
    const double fd = (k->W(r + eps) - k->W(r - eps)) / (2 * eps);
    EXPECT_NEAR(k->dWdr(r), fd, 1e-6 * std::abs(k->W(0)) / 0.1) << "r = " << r;
  }
}

// Σ_b V_b W_ab ≈ 1 on a full square lattice (Shepard sum) at h/dx = 1.3. With only 21
// neighbours the lattice sum errs by about 1% (Wendland C2: +1.05%), so a density computed
// by summation must be referred to the lattice's own sum, not to the nominal ρ.
TEST_P(KernelTest, ShepardSumOnASquareLatticeIsOne) {
  const double dx = 0.01;
  const auto k = makeKernel(GetParam(), 1.3 * dx, 2);
  double sum = 0;
  int neighbours = 0;
  for (int i = -5; i <= 5; ++i) {
    for (int j = -5; j <= 5; ++j) {
      const double r = dx * std::hypot(i, j);
      if (r < k->supportRadius()) ++neighbours;
      sum += dx * dx * k->W(r);
    }
  }
  EXPECT_NEAR(sum, 1.0, 0.015);
  EXPECT_EQ(neighbours, 21);  // the count quoted in the numerics note for h/dx = 1.3
}

INSTANTIATE_TEST_SUITE_P(Kernels, KernelTest, ::testing::Values("WendlandC2", "cubicSpline"));

TEST(KernelSelection, FromSchemesWithDefaultsAndErrors) {
  const auto schemes = Dictionary::parse("kernel cubicSpline;\nhOverDx 1.5;\n", "system/isphSchemes");
  const auto k = makeKernel(schemes, 0.01, 2);
  EXPECT_EQ(k->name(), "cubicSpline");
  EXPECT_DOUBLE_EQ(k->h(), 0.015);
  EXPECT_EQ(makeKernel(Dictionary::parse("", "s"), 0.01, 2)->name(), "WendlandC2");
  try {
    makeKernel(Dictionary::parse("\nkernel wendland;\n", "system/isphSchemes"), 0.01, 2);
    FAIL();
  } catch (const FatalError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(std::string(e.what()).find("WendlandC2"), std::string::npos) << e.what();
  }
}

// The case's kernel, as the solver, particleMesh and sampleForces all take it: from
// system/isphSchemes, the defaults (Wendland C2, h = 1.3 dx) without one, and hOverDx outside
// what SPH supports an error at its line.
TEST(KernelSelection, TheCasesKernelIsThatOfItsIsphSchemes) {
  const auto dir = std::filesystem::temp_directory_path() / ("isphCaseKernel-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "system");
  const auto none = caseKernel(dir, 0.01, 2);
  EXPECT_EQ(none->name(), "WendlandC2");
  EXPECT_DOUBLE_EQ(none->h(), 0.013);
  std::ofstream(dir / "system" / "isphSchemes") << "kernel cubicSpline;\nhOverDx 1.5;\n";
  const auto given = caseKernel(dir, 0.02, 2);
  EXPECT_EQ(given->name(), "cubicSpline");
  EXPECT_DOUBLE_EQ(given->h(), 0.03);
  std::ofstream(dir / "system" / "isphSchemes") << "kernel WendlandC2;\n\nhOverDx 5;\n";
  try {
    caseKernel(dir, 0.01, 2);
    FAIL() << "expected a FatalError";
  } catch (const FatalError& e) {
    EXPECT_EQ(e.where().line, 3);
    EXPECT_NE(std::string(e.what()).find("0.5 to 4"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace isph
