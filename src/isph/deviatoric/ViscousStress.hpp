#pragma once
// The deviatoric stress of the materials that have one as a viscosity (the regularised
// rigid-plastic and Newtonian models): the strain rate D, the effective viscosity η of each
// material particle at time n (EffectiveViscosity.hpp), and τ = 2 ηⁿ D as it acted in the
// step, which is what is written and what a wall force integrates.
#include <vector>

#include "core/Types.hpp"
#include "isph/discretisation/KernelGradientCorrection.hpp"
#include "isph/ParticleSystem.hpp"
#include "isph/deviatoric/StrainRate.hpp"

namespace isph {

class ViscousStress {
 public:
  // `correction` is the step's kernel gradient correction, read when the stress is computed.
  ViscousStress(const ParticleSystem& ps, const MaterialTable& materials, const KernelGradientCorrection& correction,
                double correctionMinDeterminant);

  // Strain rate and η of the material particles at the current state (η empty when no
  // material has a deviatoric stress); sets the largest η/ρ.
  void update();
  // τ = 2 ηⁿ D(u) of step `step`: u = *ustar for the semi-implicit term (Eq. 6 solved for u*),
  // uⁿ (null) for the explicit one. Not a stress re-evaluated from the corrected velocity,
  // which carries the projection's splitting error as a strain rate that no stress resisted.
  void keepActing(const std::vector<Vec3>* ustar, long step);
  // τ of step `step`, or null when no material has one; before the first step (no τ kept for
  // it), 2 η D of the state read, as the first step's predictor will see it. The largest η/ρ
  // and whether η is known, and with them the time step, stay as they were.
  const std::vector<SymmTensor>* tau(long step);

  const std::vector<double>& eta() const { return eta_; }
  // Whether η has been computed (else the time step takes the models' bound for η/ρ).
  bool known() const { return !eta_.empty(); }
  double maxNu() const { return maxNu_; }
  // A restart: whether η was known and its largest η/ρ (η itself is computed in the next step).
  void restore(bool known, double maxNu);

 private:
  const ParticleSystem& ps_;
  const MaterialTable& materials_;
  const KernelGradientCorrection& correction_;
  double minDeterminant_;
  StrainRate strain_;
  std::vector<double> eta_;  // of the material particles (time n)
  double maxNu_ = 0;         // the largest η/ρ of the last update
  std::vector<SymmTensor> tau_;
  long tauStep_ = -1;
};

}  // namespace isph
