#pragma once
// Cubic B-spline kernel (Monaghan & Lattanzio 1985), support 2h; α = 10/(7π h²) in 2D,
// 1/(π h³) in 3D. Suffers the pairing instability at large h/dx; kept as an option.
#include "sph/kernels/Kernel.hpp"

namespace isph {

class CubicSpline final : public Kernel {
 public:
  CubicSpline(double h, int dimension);
  std::string name() const override { return "cubicSpline"; }
  double supportFactor() const override { return 2.0; }
  double W(double r) const override;
  double dWdr(double r) const override;

 private:
  double alpha_;
};

}  // namespace isph
