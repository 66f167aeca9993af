#include "isph/solvers/WeaklyCompressibleSolver.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Log.hpp"
#include "isph/deviatoric/IntermediateVelocity.hpp"
#include "isph/stages/ExplicitDeviatoricTerm.hpp"

namespace isph {

namespace {

const bool registered = SolverRegistry::add("wcsph", [](const Time& time, bool parallel) {
  return std::make_unique<WeaklyCompressibleSolver>(time, parallel);
});

}  // namespace

WeaklyCompressibleSolver::WeaklyCompressibleSolver(const Time& time, bool parallel) : ParticleSolver(time, parallel) {
  if (std::filesystem::exists(time.path() / "system" / "isphSolution")) {
    info("\n    system/isphSolution is not read: method wcsph has no linear solves");
  }
  const auto [elasticSound, elasticWave] = elasticPlasticSpeeds(*materials_, Method::wcsph);
  waveSpeed_ = elasticWave;
  // c0: given, else a restart's (the first start's scene), else the elastic bulk speed
  // (p = K (ρ − ρ0)/ρ0), else from the scene's height.
  double c0 = schemes_.wcsph.soundSpeed;
  std::string origin = "system/isphSchemes";
  if (c0 <= 0 && state_ && state_->soundSpeed > 0) c0 = state_->soundSpeed, origin = "the solver state";
  if (c0 <= 0 && elasticSound > 0) c0 = elasticSound, origin = "sqrt(K/rho) of the elastic-plastic material";
  if (c0 <= 0) c0 = defaultSoundSpeed(ps_, g_), origin = "10 sqrt(2 |g| H), H the scene's height";
  if (!(c0 > 0)) {
    fatalError("method wcsph: a scene at rest without gravity has no speed scale for the default sound speed; "
               "give one in system/isphSchemes, e.g. wcsph { soundSpeed 20; }");
  }
  info("    sound speed c0 = {:.4g} m/s ({})", c0, origin);
  wcsph_ = std::make_unique<WeaklyCompressibleStep>(schemes_.wcsph, schemes_.tensionCutoff, c0);
  if (freshStart_) {  // the walls' densities from the hydrostatic extrapolation of the material's pressure
    walls_->settle(*kernel_, std::vector<Vec3>(ps_.nMaterial, g_));  // u* = g dt with dt = 1
  }
  if (const auto density = readStartField<scalar>("rho"); !density.empty()) {  // a restart of a wcsph run
    wcsph_->setDensity(density);
    info("    densities of the weakly-compressible state read from {}", time.timeName());
  } else {
    wcsph_->initialiseDensity(ps_);
  }
  if (elasticWave > 0) {  // elasticPlastic: s is the state, written as tau (ElasticPlasticStress.hpp)
    elastic_ = std::make_unique<ElasticPlasticStress>();
    const auto tau = readStartField<SymmTensor>("tau");
    elastic_->initialise(ps_, tau.empty() ? nullptr : &tau);
    if (!tau.empty()) info("    deviatoric stresses of the elastic-plastic state read from {}", time.timeName());
  }
  finishConstruction();
}

const std::vector<SymmTensor>* WeaklyCompressibleSolver::deviatoricStress() {
  if (elastic_) return &elastic_->deviatoric();  // the state: s after the last step, or read
  return ParticleSolver::deviatoricStress();
}

ParticleSolver::MethodScales WeaklyCompressibleSolver::methodScales() const {
  // The acoustic Courant limit (elasticPlastic: the P wave), and the force limit from the
  // whole acceleration.
  return {.signalSpeed = waveSpeed_ > 0 ? waveSpeed_ : wcsph_->soundSpeed(), .acceleration = maxAcceleration_};
}

void WeaklyCompressibleSolver::writeMethodFields(const std::filesystem::path& cloudDir,
                                                 const FieldWriteOptions& options) const {
  writeField(cloudDir / "rho", wcsph_->density(), options);
}

void WeaklyCompressibleSolver::saveMethodState(StepState& s) const {
  s.maxAcceleration = maxAcceleration_;
  s.soundSpeed = wcsph_->soundSpeed();
}

void WeaklyCompressibleSolver::restoreMethodState(const StepState& s) { maxAcceleration_ = s.maxAcceleration; }

StepReport WeaklyCompressibleSolver::step(const Time& time) {
  ++stepsTaken_;
  const double dt = time.deltaT();
  StepReport report;
  report.ppe.converged = true;  // no PPE: nothing for stepWithRetry to redo
  {
    auto t = timer_.scope("neighbour search");
    if (reorderDue()) {
      const std::vector<int> order = reorderMaterialParticles(ps_, kernel_->supportRadius());
      wcsph_->permute(order);
      if (elastic_) elastic_->permute(order);
    }
    ps_.neighbours.build(ps_.cloud.positions, *kernel_, ps_.nMaterial);  // walls: their material neighbours
  }
  {
    auto t = timer_.scope("kernel and corrections");  // the strain rate's corrected gradients
    correction_.update(ps_, schemes_.kernelCorrection, schemes_.correctionMinDeterminant);
    if (schemes_.shifting.enabled) {  // only the shifting needs the free surface
      freeSurface_->detect(ps_);
      report.freeSurface = freeSurface_->nSurfaceMaterial();
    }
  }
  {
    auto t = timer_.scope("rheology");
    if (elastic_) {  // s^{n+1} from uⁿ, then the momentum with it: symplectic in (s, u)
      elastic_->update(ps_, *materials_, dt);
    } else {
      viscousStress_->update();
      viscousStress_->keepActing(nullptr, stepsTaken_);
    }
  }
  {
    auto t = timer_.scope("forces and density");
    advance(time, report);
  }
  auto t = timer_.scope("shifting and safeguards");
  finishStep(time, report);
  return report;
}

void WeaklyCompressibleSolver::advance(const Time& time, StepReport& report) {
  const double dt = time.deltaT();
  const double h = kernel_->h();
  {  // the walls' pressures for the force routine and the friction: the material's (pⁿ, set from
     // ρⁿ at the end of the last step, or read), extrapolated
    walls_->prepare(std::vector<char>(ps_.nMaterial, 0));
    walls_->update(std::vector<Vec3>(ps_.nMaterial, Vec3(dt * g_)), dt);
  }
  const std::vector<double> rate = wcsph_->densityRate(ps_, *kernel_, g_, h);
  // g and the explicit deviatoric term (Eq. 6 as written; elasticPlastic: its stress, below),
  // then pressure and artificial viscosity.
  if (elastic_) {
    ustar_.assign(ps_.size(), Vec3::Zero());
    for (std::size_t a = 0; a < ps_.nMaterial; ++a) ustar_[a] = ps_.cloud.U[a] + dt * g_;
    maxViscousAcceleration_ = 0;
  } else {
    maxViscousAcceleration_ = IntermediateVelocity::compute(ps_, *materials_, viscousStress_->eta(), g_, dt, h, ustar_);
  }
  const long n = static_cast<long>(ps_.nMaterial);
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < n; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    ustar_[a] += dt * (wcsph_->pressureForce(ps_, *kernel_, a) + wcsph_->artificialViscosity(ps_, h, a));
    if (elastic_) ustar_[a] += dt * wcsph_->deviatoricForce(ps_, *kernel_, elastic_->deviatoric(), a);
  }
  // Coulomb friction, limited by the wall pressures (as the explicit projection step does).
  friction_->update(ps_);
  applyExplicitFriction(*friction_, ps_, dt, ustar_, wallFriction_);
  maxAcceleration_ = 0;
  for (std::size_t a = 0; a < ps_.nMaterial; ++a) {  // symplectic Euler: u, then x with the new u
    maxAcceleration_ = std::max(maxAcceleration_, (ustar_[a] - ps_.cloud.U[a]).norm() / dt);
    ps_.cloud.U[a] = ustar_[a];
    ps_.cloud.positions[a] += dt * ps_.cloud.U[a];
  }
  wcsph_->advanceDensity(rate, dt);
  wcsph_->updatePressure(ps_);  // p^{n+1}: what is written
  report.densityVariation = wcsph_->maxDensityVariation(ps_);
  const auto [compression, a] = wcsph_->maxCompression(ps_);
  if (compression > WeaklyCompressibleStep::maxAllowedCompression) {
    fatalError(fmt::format("the weakly-compressible run lost its weak compressibility at time {}: particle {} "
                           "(origId {}) at ({:.4g} {:.4g}) is compressed by {:.3g}% (more than {:.0f}%).\n    The "
                           "last written time directory is intact; the flow is faster than the sound speed {:.4g} "
                           "m/s allows (raise wcsph soundSpeed), or the run is unstable (lower maxCo).",
                           time.timeName(), a, ps_.cloud.origId[a], ps_.cloud.positions[a].x(),
                           ps_.cloud.positions[a].y(), 100 * compression,
                           100 * WeaklyCompressibleStep::maxAllowedCompression, wcsph_->soundSpeed()));
  }
}

}  // namespace isph
