#pragma once
// The forces on every set of a dictionary at one time, as sampleForces and the solver's
// forces function object compute them: patch names resolved against the cloud, the
// deviatoric stress τ (when the cloud has one) carried to the sets' wall particles, then
// patchForces per set (with the wall friction traction, when the material slides on walls).
#include <vector>

#include "postProcessing/forces/ForceSet.hpp"
#include "postProcessing/forces/PatchForces.hpp"
#include "sph/kernels/Kernel.hpp"
#include "sph/neighbours/NeighbourList.hpp"

namespace isph {

struct SetForcesInput {
  const ParticleCloud& cloud;
  const std::vector<ForceSet>& sets;
  const std::vector<SymmTensor>* tau = nullptr;  // per particle (material entries used); null: none
  const Kernel* kernel = nullptr;                // for the τ average; required when tau is given
  // The caller's neighbour list over cloud.positions, if it has one (the solver); else one
  // is built here when tau is given.
  const NeighbourList* neighbours = nullptr;
  // The solver's Coulomb friction traction on the wall particles (field wallFriction), or null.
  const std::vector<Vec3>* wallFriction = nullptr;
  // A parallel run: this rank's own particles (PatchForces.hpp); null: serial.
  const std::vector<char>* owned = nullptr;
};

std::vector<PatchForces> setForces(const SetForcesInput& in);

}  // namespace isph
