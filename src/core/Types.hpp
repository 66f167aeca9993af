#pragma once
// Primitive types shared by every library: scalars, labels and the small fixed-size
// vectors and tensors that particle fields hold (OpenFOAM's names, Eigen underneath).
#include <Eigen/Core>
#include <cstdint>

namespace isph {

using scalar = double;
using label = std::int32_t;  // particle counts and ids; 2^31 particles is far beyond one node

using Vec3 = Eigen::Vector3d;  // positions, velocities, normals (z = 0 in 2D scenes)

// Symmetric tensor in OpenFOAM's component order: xx xy xz yy yz zz.
using SymmTensor = Eigen::Matrix<double, 6, 1>;

// t·n of a symmetric tensor (the traction on a plane of normal n).
inline Vec3 dotSymm(const SymmTensor& t, const Vec3& n) {
  return Vec3(t[0] * n.x() + t[1] * n.y() + t[2] * n.z(),  //
              t[1] * n.x() + t[3] * n.y() + t[4] * n.z(),  //
              t[2] * n.x() + t[4] * n.y() + t[5] * n.z());
}

// t:t of a symmetric tensor (each off-diagonal component counted twice).
inline double doubleDotSymm(const SymmTensor& t) {
  return t[0] * t[0] + t[3] * t[3] + t[5] * t[5] + 2.0 * (t[1] * t[1] + t[2] * t[2] + t[4] * t[4]);
}

}  // namespace isph
