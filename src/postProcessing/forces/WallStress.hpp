#pragma once
// The material's deviatoric stress τ carried to the wall particles, where the force on a
// patch is summed: a Shepard (normalised kernel) average over the material neighbours b of
// each wall particle w,
//     τ_w = Σ_b τ_b W_wb / Σ_b W_wb        (b: kind material; equal particle volumes),
// zero where a wall particle has no material neighbour. Only wall particles get a value;
// material and dummy particles get zero.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "particles/ParticleCloud.hpp"
#include "sph/neighbours/NeighbourList.hpp"

namespace isph {

// `tau`: one value per particle of `cloud` (only material entries are used). `neighbours`
// must have been built over cloud.positions (the solver's list, or one built for the purpose).
// `selected` (optional, one flag per particle) limits the work to the wall particles flagged.
std::vector<SymmTensor> wallDeviatoricStress(const ParticleCloud& cloud, const std::vector<SymmTensor>& tau,
                                             const NeighbourList& neighbours,
                                             const std::vector<char>* selected = nullptr);

// The deviatoric stress field `tau` (symmTensorField) of cloud `cloudName` in `timeDir`, if the
// solver wrote one (the material has a deviatoric stress); empty otherwise. Checks its length.
std::optional<std::vector<SymmTensor>> readDeviatoricStress(const std::filesystem::path& timeDir,
                                                            const std::string& cloudName, std::size_t n);

// The Coulomb wall friction traction `wallFriction` (vectorField, Pa) of cloud `cloudName` in
// `timeDir`, if the solver wrote one (some material slides on a friction wall); empty otherwise.
std::optional<std::vector<Vec3>> readWallFriction(const std::filesystem::path& timeDir, const std::string& cloudName,
                                                  std::size_t n);

}  // namespace isph
