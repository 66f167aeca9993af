#pragma once
// The explicit weakly-compressible baseline (`method wcsph;`, WeaklyCompressibleStep.hpp):
// the approach the paper argues against, over the same particles, rheology, wall friction and
// force routine as the projection. Per step:
//   neighbours → kernel correction (and the free surface, for shifting) → the deviatoric
//   stress (the regularised viscosity, or the elastic-plastic s of ElasticPlasticStress) →
//   density rate → u^{n+1} from g, the deviatoric term, the pressure force, the artificial
//   viscosity and the wall friction → x^{n+1} with u^{n+1} (symplectic Euler) → ρ^{n+1} and
//   p^{n+1} from the equation of state → shift → wall safeguard (ParticleSolver::finishStep)
// The time step is the acoustic one (the P wave's for elasticPlastic materials). It runs on one
// rank, without linear solves (system/isphSolution is not read).
#include <memory>

#include "isph/deviatoric/ElasticPlasticStress.hpp"
#include "isph/solvers/WeaklyCompressibleStep.hpp"
#include "isph/solvers/ParticleSolver.hpp"

namespace isph {

class WeaklyCompressibleSolver final : public ParticleSolver {
 public:
  // Reads the case (ParticleSolver) and, for a restart, the densities (field rho) and the
  // elastic-plastic deviatoric stress (field tau) of the start time.
  WeaklyCompressibleSolver(const Time& time, bool parallel);

  StepReport step(const Time& time) override;
  // s of the elastic-plastic state, or the viscous τ that acted in the last step.
  const std::vector<SymmTensor>* deviatoricStress() override;

 private:
  MethodScales methodScales() const override;
  void writeMethodFields(const std::filesystem::path& cloudDir, const FieldWriteOptions& options) const override;
  void saveMethodState(StepState& s) const override;
  void restoreMethodState(const StepState& s) override;
  std::string wallCondition() const override { return "dynamic boundary particles"; }

  // u^{n+1}, x^{n+1}, ρ^{n+1} and p^{n+1}; FatalError when a particle is compressed beyond
  // WeaklyCompressibleStep::maxAllowedCompression.
  void advance(const Time& time, StepReport& report);

  std::unique_ptr<WeaklyCompressibleStep> wcsph_;
  std::unique_ptr<ElasticPlasticStress> elastic_;  // elasticPlastic materials (null: viscous)
  double waveSpeed_ = 0;        // elasticPlastic: the P-wave speed, the acoustic Courant limit's
  double maxAcceleration_ = 0;  // the largest |du/dt| of the last step (force limit)
};

}  // namespace isph
