#pragma once
// Rigid-perfectly-plastic soil with a Drucker-Prager (Coulomb) yield surface, the paper's
// Eq. 3, selected by `model rigidPlastic;` in constant/materialProperties:
//
//   s_ij = p sin φ ε̇_ij / |ε̇|     (compression positive, ε̇ the deviatoric strain rate, Eqs. 4-5)
//
// Norm: |ε̇| = √(½ ε̇:ε̇), the plane-strain Mohr-Coulomb reading, so that in simple shear
// |s_xy| = p sin φ and √(½ s:s) = p sin φ. Written as an effective viscosity with the
// rate of deformation D = −ε̇ and |γ̇| = √(2 D:D) (= |∂u/∂y| in simple shear):
//
//   s = 2 η D,   η = sin φ_e · p / |γ̇|,   regularised η ← clamp(η, etaMin, etaMax)
//
// etaMax bounds the viscosity of the rigid limit (|γ̇| → 0): a zone below yield creeps at
// |γ̇| ≈ sin φ p / etaMax. Default 10⁴ ρ √(g H³) with H the material's height along g
// (numerics.md §4, after Lagrée et al. 2011). etaMin keeps η > 0 where p → 0 (free surface);
// default ρ dx √(g dx) (a grain-inertia viscosity with the grain size replaced by dx).
// φ_e is φ, or the equivalent friction of Eq. 12 when `phiEquivalent` or `waterTable` is given.
//
// The pressure in the strength is p + ½ ρ |g| dx: the free-surface condition holds p = 0 at
// the centres of the surface particles, half a spacing below the material's real surface,
// while the weight above a particle (the shear stress on a slope) counts from the real
// surface. Without the half layer, the top rows of a layer on a slope steeper than
// atan(sin φ / 3) yield although the slope itself is stable.
#include <optional>
#include <string>

#include "isph/materials/MaterialModel.hpp"

namespace isph {

class DruckerPragerRigidPlastic final : public MaterialModel {
 public:
  DruckerPragerRigidPlastic(const std::string& name, const Dictionary& dict);

  std::string type() const override { return "rigidPlastic"; }
  bool hasDeviatoricStress() const override { return true; }
  double viscosity(double p, double shearRate) const override;
  double maxViscosity() const override { return etaMax_; }
  WallContact wallContact() const override { return WallContact::coulombFriction; }
  bool granular() const override { return true; }
  void adaptToScene(const SceneScales& scene) override;
  std::string describe() const override;

  double phi() const { return phi_; }
  double phiEffective() const { return phiEffective_; }
  double frictionCoefficient() const { return mu_; }  // sin φ_e
  double etaMin() const { return etaMin_; }

 private:
  double phi_ = 0;           // φ_crit [deg]
  double phiEffective_ = 0;  // φ_e [deg] (Eq. 12) or φ
  double mu_ = 0;            // sin φ_e
  std::string frictionNote_;  // how φ_e was obtained, for the log
  std::optional<double> etaMaxGiven_, etaMinGiven_;
  double etaMax_ = 0, etaMin_ = 0;
  double surfacePressure_ = 0;  // ½ ρ |g| dx
  std::string etaNote_;
};

}  // namespace isph
