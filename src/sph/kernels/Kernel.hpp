#pragma once
// A smoothing kernel W(r, h) with compact support `supportFactor() * h`. Kernels are
// chosen by name in system/isphSchemes (`kernel WendlandC2;`) from the kernel registry.
#include <filesystem>
#include <memory>
#include <string>

#include "core/Error.hpp"

namespace isph {

class Dictionary;

class Kernel {
 public:
  Kernel(double h, int dimension) : h_(h), dimension_(dimension) {}
  virtual ~Kernel() = default;

  virtual std::string name() const = 0;
  // Support radius in units of h (2 for both kernels shipped).
  virtual double supportFactor() const = 0;
  virtual double W(double r) const = 0;
  // dW/dr (<= 0); the gradient is dWdr(r) * x_ab / r.
  virtual double dWdr(double r) const = 0;

  double h() const { return h_; }
  int dimension() const { return dimension_; }
  double supportRadius() const { return supportFactor() * h_; }

 protected:
  double h_;
  int dimension_;
};

// The kernel named in `schemes` (`kernel`, default WendlandC2) with h = hOverDx * dx
// (`hOverDx`, default 1.3): the one reader of these two keywords of system/isphSchemes, for
// the solver, particleMesh (the wall layers' depth) and sampleForces.
std::unique_ptr<Kernel> makeKernel(const Dictionary& schemes, double dx, int dimension);
// The same from <caseDir>/system/isphSchemes (the defaults when the case has none).
std::unique_ptr<Kernel> caseKernel(const std::filesystem::path& caseDir, double dx, int dimension);

// Kernel by name (FatalError listing the valid names for an unknown one).
std::unique_ptr<Kernel> makeKernel(const std::string& name, double h, int dimension,
                                   const SourceLocation& where = {});

}  // namespace isph
