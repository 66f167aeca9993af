#include "sph/kernels/WendlandC2.hpp"

#include <cmath>
#include <numbers>

#include "core/Registry.hpp"

namespace isph {

namespace {
const bool registered = Registry<Kernel, double, int>::add(
    "WendlandC2", [](double h, int dim) { return std::make_unique<WendlandC2>(h, dim); });
}

WendlandC2::WendlandC2(double h, int dimension) : Kernel(h, dimension) {
  if (dimension == 2) {
    alpha_ = 7.0 / (4.0 * std::numbers::pi * h * h);
  } else if (dimension == 3) {
    alpha_ = 21.0 / (16.0 * std::numbers::pi * h * h * h);
  } else {
    fatalError("WendlandC2 kernel: dimension must be 2 or 3");
  }
}

double WendlandC2::W(double r) const {
  const double q = r / h_;
  if (q >= 2.0) return 0.0;
  const double a = 1.0 - 0.5 * q;
  return alpha_ * a * a * a * a * (2.0 * q + 1.0);
}

double WendlandC2::dWdr(double r) const {
  const double q = r / h_;
  if (q >= 2.0) return 0.0;
  const double a = 1.0 - 0.5 * q;
  return -5.0 * alpha_ * q * a * a * a / h_;
}

}  // namespace isph
