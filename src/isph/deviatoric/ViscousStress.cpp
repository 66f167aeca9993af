#include "isph/deviatoric/ViscousStress.hpp"

#include "isph/deviatoric/EffectiveViscosity.hpp"

namespace isph {

ViscousStress::ViscousStress(const ParticleSystem& ps, const MaterialTable& materials,
                             const KernelGradientCorrection& correction, double correctionMinDeterminant)
    : ps_(ps), materials_(materials), correction_(correction), minDeterminant_(correctionMinDeterminant) {}

void ViscousStress::update() {
  if (!materials_.anyDeviatoricStress()) {
    eta_.clear();
    return;
  }
  strain_.compute(ps_, materials_, correction_, minDeterminant_);
  maxNu_ = effectiveViscosity(ps_, materials_, strain_, eta_);
}

void ViscousStress::keepActing(const std::vector<Vec3>* ustar, long step) {
  if (!materials_.anyDeviatoricStress()) return;
  if (ustar) {
    StrainRate acting;
    acting.compute(ps_, materials_, correction_, minDeterminant_, *ustar);
    tau_ = deviatoricStress(ps_, acting, eta_);
  } else {
    tau_ = deviatoricStress(ps_, strain_, eta_);
  }
  tauStep_ = step;
}

const std::vector<SymmTensor>* ViscousStress::tau(long step) {
  if (!materials_.anyDeviatoricStress()) return nullptr;
  if (tauStep_ != step) {
    // (The time step must not depend on whether a write asked: the largest η/ρ stays, and so
    // does whether η is known, else a write before the first step would leave known() with
    // maxNu() 0 and no viscous limit in place of the models' bound.)
    const double maxNu = maxNu_;
    const bool known = this->known();
    update();
    tau_ = deviatoricStress(ps_, strain_, eta_);
    tauStep_ = step;
    maxNu_ = maxNu;
    if (!known) eta_.clear();
  }
  return &tau_;
}

void ViscousStress::restore(bool known, double maxNu) {
  maxNu_ = maxNu;
  if (known) eta_.assign(ps_.nMaterial, 0.0);  // only whether η exists matters before the next step
}

}  // namespace isph
