#pragma once
// The deviatoric stress of elastic-plastic materials (model elasticPlastic,
// DruckerPragerElasticPlastic) in the weakly-compressible method: s per material particle,
// advanced once per step from the velocity gradient by the material's law (Jaumann rate,
// return to the yield surface at the particle's pressure). The mean stress is the
// weakly-compressible pressure (WeaklyCompressibleStep).
//
// The velocity gradient is the plain SPH difference gradient over the material neighbours,
//   ∇u_a = Σ_b V_b (u_b − u_a) ⊗ ∇_a W_ab,
// the discrete adjoint of the symmetric divergence that s acts through (stressForce): with the
// renormalised gradient instead, a layer at rest gained energy and flowed after 0.05 s. The
// walls add no shear (Coulomb friction acts there, WallFriction).
//
// s is the state: it is the τ written in every time directory (field tau), from which a
// restart continues; a case without it starts from s = 0 (an isotropic stress, −p I).
#include <utility>
#include <vector>

#include "core/Types.hpp"
#include "isph/IsphSchemes.hpp"
#include "isph/ParticleSystem.hpp"
#include "isph/materials/MaterialTable.hpp"

namespace isph {

class ElasticPlasticStress {
 public:
  // s of the material particles: `written` (a restart's tau, one per particle of ps), else 0.
  void initialise(const ParticleSystem& ps, const std::vector<SymmTensor>* written);
  // s^{n+1} from sⁿ, the pressure and the velocity of the particles (all elasticPlastic).
  void update(const ParticleSystem& ps, const MaterialTable& materials, double dt);
  // s of every particle of ps (walls and dummies: zero).
  const std::vector<SymmTensor>& deviatoric() const { return s_; }
  // Follows the cell reordering of the material particles (order[new] = old).
  void permute(const std::vector<int>& order);

 private:
  std::vector<SymmTensor> s_;
};

// The largest sound speed √(K/ρ) and P-wave speed of the scene's elasticPlastic materials
// (0, 0: none). FatalError if such a material shares the scene with another model or runs
// with the projection method.
std::pair<double, double> elasticPlasticSpeeds(const MaterialTable& materials, Method method);

}  // namespace isph
