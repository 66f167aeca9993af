#pragma once
// Wendland C2 kernel (Wendland 1995; Dehnen & Aly 2012): no pairing instability, smooth
// gradient. q = r/h, support 2h: W = α (1 - q/2)^4 (2q + 1), α = 7/(4π h²) in 2D,
// 21/(16π h³) in 3D.
#include "sph/kernels/Kernel.hpp"

namespace isph {

class WendlandC2 final : public Kernel {
 public:
  WendlandC2(double h, int dimension);
  std::string name() const override { return "WendlandC2"; }
  double supportFactor() const override { return 2.0; }
  double W(double r) const override;
  double dWdr(double r) const override;

 private:
  double alpha_;
};

}  // namespace isph
