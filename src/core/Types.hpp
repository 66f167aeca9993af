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

}  // namespace isph
