#pragma once
// Elastic-perfectly-plastic soil with a Drucker-Prager yield surface (Bui et al. 2008), selected
// by `model elasticPlastic;` in constant/materialProperties, for `method wcsph;` only: the
// method users of weakly-compressible SPH pick for soil, the baseline that the projection
// method is charted against (tutorials/benchmarks/speedAccuracy). Entries: rho, phi [deg],
// cohesion [Pa] (default 0), E [Pa], nu. Non-dilatant (ψ = 0).
//
// Stress σ = −p I + s, tension positive; the deviatoric part s is the full 3×3 (plane strain
// keeps s_zz). The mean stress is the weakly-compressible pressure p = K (ρ − ρ0)/ρ0 of the
// continuity equation (WeaklyCompressibleStep with c0 = √(K/ρ0): the hypoelastic law's
// isotropic part, ṗ = −K ∇·u, kept in step with the density as SPHinXsys' plastic continuum
// does); s follows the hypoelastic law with the Jaumann rate and returns to the yield surface:
//   s* = s + dt (ω s − s ω + 2 G ė'),  ė' = dev ½(∇u + ∇uᵀ),  ω = ½(∇u − ∇uᵀ)
//   f = α_φ I1 + √J2 − k_c,  I1 = −3p,  J2 = ½ s:s  (plane-strain fit to Mohr-Coulomb)
//   α_φ = tan φ / √(9 + 12 tan² φ),  k_c = 3 c / √(9 + 12 tan² φ)
//   f(s*) > 0:  s ← s* (k_c + 3 α_φ p)/√J2*   (Bui's stress scaling; s = 0 if that is < 0)
//   K = E / (3 (1 − 2ν)), G = E / (2 (1 + ν)).
// Walls: Coulomb friction (WallFriction), as the rigid-plastic model.
#include <string>

#include <Eigen/Core>

#include "core/Types.hpp"
#include "isph/materials/MaterialModel.hpp"

namespace isph {

class DruckerPragerElasticPlastic final : public MaterialModel {
 public:
  DruckerPragerElasticPlastic(const std::string& name, const Dictionary& dict);

  std::string type() const override { return "elasticPlastic"; }
  bool hasDeviatoricStress() const override { return true; }
  // The stress is integrated (updateDeviatoric), not derived from a viscosity.
  bool integratesStress() const override { return true; }
  double viscosity(double, double) const override { return 0.0; }
  double maxViscosity() const override { return 0.0; }
  WallContact wallContact() const override { return WallContact::coulombFriction; }
  bool granular() const override { return true; }
  std::string describe() const override;

  double bulkModulus() const { return K_; }
  double shearModulus() const { return G_; }
  // √(K/ρ): the weakly-compressible sound speed of the pressure's equation of state.
  double bulkSpeed() const;
  // The P-wave speed √((K + 4G/3)/ρ): the speed the explicit step must resolve.
  double waveSpeed() const;
  double alphaPhi() const { return alphaPhi_; }
  double kc() const { return kc_; }

  // s^{n+1} from sⁿ, the pressure p (compression positive) and ∇u (∂u_i/∂x_j) over dt.
  SymmTensor updateDeviatoric(const SymmTensor& s, double p, const Eigen::Matrix3d& gradU, double dt) const;
  // A trial deviatoric stress returned to the yield surface at pressure p (unchanged inside).
  SymmTensor returnToYieldSurface(const SymmTensor& s, double p) const;
  // f [Pa] of the stress −p I + s: > 0 outside the yield surface.
  double yieldFunction(const SymmTensor& s, double p) const;

 private:
  double phi_ = 0, cohesion_ = 0, E_ = 0, nu_ = 0;
  double K_ = 0, G_ = 0;
  double alphaPhi_ = 0, kc_ = 0;
};

}  // namespace isph
