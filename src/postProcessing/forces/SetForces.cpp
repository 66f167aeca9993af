#include "postProcessing/forces/SetForces.hpp"

#include "postProcessing/forces/WallStress.hpp"

namespace isph {

std::vector<PatchForces> setForces(const SetForcesInput& in) {
  const ParticleCloud& cloud = in.cloud;
  std::vector<std::vector<label>> labels;
  std::vector<char> patchUsed(cloud.properties.patches.size(), 0);
  for (const auto& set : in.sets) {
    labels.push_back(patchLabels(set, cloud.properties));
    for (const label p : labels.back()) patchUsed[static_cast<std::size_t>(p)] = 1;
  }

  std::vector<SymmTensor> wallTau;
  if (in.tau) {
    if (!in.kernel && !in.neighbours) fatalError("setForces: a deviatoric stress field needs a kernel");
    NeighbourList own;
    if (!in.neighbours) own.build(cloud.positions, *in.kernel);
    std::vector<char> selected(cloud.size(), 0);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      selected[i] = cloud.patch[i] >= 0 && patchUsed[static_cast<std::size_t>(cloud.patch[i])];
    }
    wallTau = wallDeviatoricStress(cloud, *in.tau, in.neighbours ? *in.neighbours : own, &selected);
  }

  std::vector<PatchForces> out;
  for (std::size_t s = 0; s < in.sets.size(); ++s) {
    out.push_back(patchForces({.cloud = cloud,
                               .patches = labels[s],
                               .wallTau = in.tau ? &wallTau : nullptr,
                               .wallFriction = in.wallFriction,
                               .CofR = in.sets[s].CofR,
                               .width = cloud.properties.dimension == 2 ? in.sets[s].widthOrUnit() : 1.0,
                               .facing = in.sets[s].facing.value_or(Vec3::Zero()),
                               .owned = in.owned}));
  }
  return out;
}

}  // namespace isph
