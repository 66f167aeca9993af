#include "sph/kernels/CubicSpline.hpp"

#include <cmath>
#include <numbers>

#include "core/Registry.hpp"

namespace isph {

namespace {
const bool registered = Registry<Kernel, double, int>::add(
    "cubicSpline", [](double h, int dim) { return std::make_unique<CubicSpline>(h, dim); });
}

CubicSpline::CubicSpline(double h, int dimension) : Kernel(h, dimension) {
  if (dimension == 2) {
    alpha_ = 10.0 / (7.0 * std::numbers::pi * h * h);
  } else if (dimension == 3) {
    alpha_ = 1.0 / (std::numbers::pi * h * h * h);
  } else {
    fatalError("cubicSpline kernel: dimension must be 2 or 3");
  }
}

double CubicSpline::W(double r) const {
  const double q = r / h_;
  if (q >= 2.0) return 0.0;
  if (q < 1.0) return alpha_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
  const double a = 2.0 - q;
  return alpha_ * 0.25 * a * a * a;
}

double CubicSpline::dWdr(double r) const {
  const double q = r / h_;
  if (q >= 2.0) return 0.0;
  if (q < 1.0) return alpha_ * (-3.0 * q + 2.25 * q * q) / h_;
  const double a = 2.0 - q;
  return -alpha_ * 0.75 * a * a / h_;
}

}  // namespace isph
