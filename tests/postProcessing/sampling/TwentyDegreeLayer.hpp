#pragma once
// The layer both sampling tests build: sand (rho 1800) 0.1 m deep on a 0.01 m lattice,
// x in (0, 0.6), under gravity tilted by 20 degrees; its interior away from the end walls
// and below the top row.
#include <cmath>

#include "postProcessing/sampling/Lithostatic.hpp"

namespace isph::test {

constexpr double rho = 1800, gMag = 9.81, beta = 20 * M_PI / 180, H = 0.1;

inline LithostaticSpec twentyDegreeLayerSpec() {
  LithostaticSpec s;
  s.rho = rho;
  s.g = gMag * Vec3(std::sin(beta), -std::cos(beta), 0);
  s.xMin = 0.15;
  s.xMax = 0.45;
  s.minDepth = 0.015;  // between the rows at depths 0.01 and 0.02
  s.height = H;
  return s;
}

}  // namespace isph::test
