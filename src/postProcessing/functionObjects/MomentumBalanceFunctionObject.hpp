#pragma once
// Function object `momentumBalance`: the material's momentum budget, a load cell under the
// whole scene. From the material particles' masses and velocities alone, every
// writeInterval steps:
//
//   F = M g − dP/dt      (Newton's second law over the material, P = Σ m u, M = Σ m)
//
// is the force of the material on everything that holds it: all walls together. It is exact
// over each interval between two rows (dP/dt is the mean over that interval), whatever the
// wall force routine makes of the wall pressures. For material at rest F = M g. Compare it
// with a patchForces set over all the patches: their difference is that routine's error
// (the sum of the wall particles' pressures and frictions for a discrete pressure field),
// plus whatever momentum the discrete forces inside the material do not conserve (the
// difference form of the pressure gradient, Eq. 11, is not pairwise antisymmetric).
//
//   loadCell
//   {
//       type          momentumBalance;
//       width         0.3;         // optional (2D): over this width [N], else per metre [N/m]
//       writeInterval 1;           // optional: every N time steps (default 1)
//   }
//
// Output: postProcessing/<name>/<startTime>/momentum.dat, a `# Time [s] M [kg] ...` line
// naming every column and unit, then one row per execution after the first (the first only
// records P): Time M Px Py dPx/dt dPy/dt Wx Wy Fx Fy (3D adds the z components). Each row is
// written with one write and flushed, as patchForces' (PatchForcesFunctionObject.hpp).
#include <filesystem>
#include <optional>

#include "postProcessing/functionObjects/FunctionObject.hpp"
#include "postProcessing/functionObjects/RowFile.hpp"

namespace isph {

class MomentumBalanceFunctionObject final : public FunctionObject {
 public:
  MomentumBalanceFunctionObject(const std::string& name, const Dictionary& dict, const Time& time);

  std::string type() const override { return "momentumBalance"; }
  void execute(const Time& time, const SolverState& state) override;
  std::string describe() const override;

  const std::filesystem::path& file() const { return file_; }

 private:
  std::optional<double> width_;
  std::filesystem::path file_;
  RowFile out_;
  bool havePrevious_ = false;
  double previousTime_ = 0;
  Vec3 previousMomentum_ = Vec3::Zero();
};

}  // namespace isph
