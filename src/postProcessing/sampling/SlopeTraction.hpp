#pragma once
// What statics fixes in a granular layer at rest on an infinite slope: the traction on
// planes parallel to the bed. A rigid-plastic body at rest has a statically undetermined mean
// pressure (its K0), but the block above depth d must be held by the traction under it, so
//
//   σ·n = ρ d g     (σ = −p I + τ, tension positive; n the bed normal out of the layer)
//
// normal part: σ_nn = p − n·τ·n = ρ |g| cos β d (compression positive),
// shear part:  σ_nt = (I − n nᵀ) τ n = ρ d g_t, |σ_nt| = ρ |g| sin β d.
// The depth d is measured from the material's real surface, half a spacing above the
// highest particle centre: each particle carries the material from its centre to the upper
// edge of its own cell, so the stress at a particle centre carries the weight above that
// edge (the rows above plus its own upper half).
//   - l2Normal, l2Shear: relative L2 errors over all material particles;
//   - spreadNormal, spreadShear: max − min of the error over the interior (xMin < x < xMax,
//     deeper than minDepth), in units of ρ |g| H;
//   - atYield: the share of the material particles whose |τ| = √(τ:τ/2) reaches 0.99 of the
//     rigid-plastic strength sin φ (p + ½ ρ |g| dx) (DruckerPragerRigidPlastic), when φ > 0.
#include <vector>

#include "core/Types.hpp"
#include "particles/ParticleCloud.hpp"
#include "postProcessing/sampling/Lithostatic.hpp"

namespace isph {

struct SlopeTractionError {
  double l2Normal = 0.0, l2Shear = 0.0;
  double spreadNormal = 0.0, spreadShear = 0.0;
  double atYield = 0.0;  // share of the material particles at yield (0 when phi is 0)
  std::size_t interior = 0;
};

// `tau`: the deviatoric stress of every particle of `cloud` (the written field `tau`);
// `phi` [deg]: the material's friction angle, or 0 to skip the yield count. FatalError as
// lithostaticError, or when tau's size differs from the cloud's.
SlopeTractionError slopeTractionError(const ParticleCloud& cloud, const std::vector<SymmTensor>& tau,
                                      const LithostaticSpec& spec, double phi = 0.0);

}  // namespace isph
