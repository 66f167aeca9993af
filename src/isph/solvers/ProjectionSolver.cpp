#include "isph/solvers/ProjectionSolver.hpp"

#include <fmt/format.h>

#include "core/Log.hpp"
#include "isph/ElasticPlasticStress.hpp"
#include "isph/IntermediateVelocity.hpp"
#include "isph/LaggedPressure.hpp"
#include "isph/SchemeConflicts.hpp"
#include "isph/VelocityCorrection.hpp"
#include "isph/parallel/GhostExchange.hpp"

namespace isph {

namespace {

const bool registered = SolverRegistry::add(
    "isph", [](const Time& time, bool parallel) { return std::make_unique<ProjectionSolver>(time, parallel); });

}  // namespace

ProjectionSolver::ProjectionSolver(const Time& time, bool parallel) : ParticleSolver(time, parallel) {
  elasticPlasticSpeeds(*materials_, Method::isph);  // FatalError: elasticPlastic materials are not for this method
  info("\nReading system/isphSolution");
  const Dictionary solution = Dictionary::readOptionalFile(time.path() / "system" / "isphSolution", "system/isphSolution");
  std::vector<char> keepCompressed(materials_->size(), 0);
  for (std::size_t i = 0; i < materials_->size(); ++i) {
    keepCompressed[i] = schemes_.compressedSurface == CompressedSurface::all ||
                        (schemes_.compressedSurface == CompressedSurface::granular &&
                         (*materials_)[i].granular());
  }
  ppe_ = std::make_unique<PressurePoissonEquation>(schemes_.ppe, schemes_.tensionCutoff, makeLinearSolver(solution.subDictOrEmpty("p"), "p"),
                                                   std::move(keepCompressed));
  if (materials_->anyDeviatoricStress() && schemes_.viscousTerm == ViscousTerm::implicit) {
    viscous_ = std::make_unique<ImplicitViscousStep>(solution.subDictOrEmpty("U"), ps_.cloud.properties.dimension,
                                                     schemes_.frictionPasses);
    incremental_ = schemes_.incrementalPressure == MaterialScope::all ||
                   (schemes_.incrementalPressure == MaterialScope::granular && materials_->anyGranular());
  }
  solution.checkKeywords({"U"});
  checkSchemesForScene(schemes_, incremental_);
  finishConstruction();
}

void ProjectionSolver::saveMethodState(StepState& s) const {
  if (viscous_) viscous_->saveState(s);
}

void ProjectionSolver::restoreMethodState(const StepState& s) {
  if (viscous_) viscous_->restoreState(s);
}

void ProjectionSolver::afterWrite() {
  ppe_->renumbered();
  if (viscous_) viscous_->renumbered();
}

std::string ProjectionSolver::preconditionerSummary() const {
  std::string s = fmt::format("AMG hierarchies built for p: {} of {} solves", ppe_->solver().preconditionersBuilt(),
                              ppe_->solver().solvesDone());
  if (viscous_) {
    s += fmt::format("\nAMG hierarchies built for U: {} of {} solves", viscous_->preconditionersBuilt(),
                     viscous_->solvesDone());
    if (viscous_->frictionSolves() > 0) {
      s += fmt::format("\nBed friction: stick/slip states settled in {} of {} steps ({:.2f} passes per step, at most {})",
                       viscous_->frictionSolvesSettled(), viscous_->frictionSolves(),
                       static_cast<double>(viscous_->frictionPassesDone()) / viscous_->frictionSolves(),
                       viscous_->maxFrictionPasses());
    }
  }
  return s;
}

void ProjectionSolver::laggedPressure(double dt, std::vector<Vec3>& reaction) {
  // The incremental projection (see the header): the viscous solve sees the pressure force of
  // the last step, −∇pⁿ/ρ (the walls' condition of a material at rest, ũ = uⁿ + dt g).
  lagged_.resize(ps_.nMaterial);
  std::vector<Vec3> resting(ps_.cloud.U);
  for (std::size_t a = 0; a < ps_.nMaterial; ++a) resting[a] += dt * g_;
  const long n = static_cast<long>(ps_.nMaterial);
  if (schemes_.laggedForm == LaggedPressureForm::gradient) {
    // The gradient of Eq. 11 of p̃ (LaggedPressure.hpp); the PPE then solves for p^{n+1} − p̃.
    if (schemes_.laggedSmoothing > 0) {
      const std::vector<double> smooth = smoothedPressure(ps_, *kernel_, freeSurface_->flags(), schemes_.laggedSmoothing);
      std::copy(smooth.begin(), smooth.end(), ps_.cloud.p.begin());
    }
#pragma omp parallel for schedule(static)
    for (long ia = 0; ia < n; ++ia) {
      const auto a = static_cast<std::size_t>(ia);
      lagged_[a] = -pressureGradient(ps_, correction_, resting, g_, a, dt) / ps_.rho[a];
    }
  } else {
    reaction.assign(ps_.nMaterial, Vec3::Zero());
#pragma omp parallel for schedule(static)
    for (long ia = 0; ia < n; ++ia) {
      const auto a = static_cast<std::size_t>(ia);
      lagged_[a] = laggedPressureForce(ps_, *kernel_, resting, g_, a, dt, &reaction[a]);
    }
  }
  exchangeGhosts(ps_, lagged_);  // parallel: the walls' pressure reads it at ghosts
}

void ProjectionSolver::intermediateVelocity(const Time& time, StepReport& report) {
  const double dt = time.deltaT();
  {
    auto t = timer_.scope("rheology");
    viscousStress_->update();
    lagged_.clear();
    std::vector<Vec3> reaction;
    if (incrementalNow()) laggedPressure(dt, reaction);
    friction_->update(ps_, reaction.empty() ? nullptr : &reaction);
  }
  if (viscous_) {
    const auto perf = viscous_->solve(ps_, *materials_, viscousStress_->eta(), friction_.get(), g_, dt, kernel_->h(),
                                      lagged_, ustar_);
    exchangeGhosts(ps_, ustar_);  // parallel: solved for the own particles
    report.viscous.insert(report.viscous.end(), perf.begin(), perf.end());
    timer_.add("viscous assembly", viscous_->assemblySeconds());
    for (const auto& perf : report.viscous) {
      timer_.add("viscous assembly", perf.assemblySeconds);
      timer_.add("viscous setup", perf.setupSeconds);
      timer_.add("viscous solve", perf.solveSeconds);
    }
    maxViscousAcceleration_ = 0;
    if (friction_->active()) {
      std::vector<Vec3> force = viscous_->frictionForce();
      if (!force.empty()) {  // parallel: solved for the own rows
        force.resize(ps_.nMaterial, Vec3::Zero());
        exchangeGhosts(ps_, force);
      }
      wallFriction_ = friction_->wallTraction(ps_, force);
    }
    auto t = timer_.scope("rheology");
    viscousStress_->keepActing(&ustar_, stepsTaken_);  // u* with its ghosts (exchanged above)
    return;
  }
  auto t = timer_.scope("intermediate velocity");
  viscousStress_->keepActing(nullptr, stepsTaken_);
  maxViscousAcceleration_ =
      IntermediateVelocity::compute(ps_, *materials_, viscousStress_->eta(), g_, dt, kernel_->h(), ustar_);
  applyExplicitFriction(dt);
  exchangeGhosts(ps_, ustar_);  // parallel
}

void ProjectionSolver::correctAndMove(double dt) {
  std::vector<Vec3> oldU(ps_.cloud.U.begin(), ps_.cloud.U.begin() + static_cast<long>(ps_.nMaterial));
  if (!lagged_.empty()) {
    correctVelocityIncrement(ps_, correction_, ustar_, increment_, dt);
    exchangeGhosts(ps_, ps_.cloud.U);  // parallel
    std::vector<Vec3> ustarTotal(ustar_);  // the walls' pressure from the whole condition
    for (std::size_t a = 0; a < ps_.nMaterial; ++a) ustarTotal[a] -= dt * lagged_[a];
    walls_->update(ustarTotal, dt);
  } else {
    correctVelocity(ps_, correction_, ustar_, g_, dt,
                    schemes_.pressureGradient == PressureGradientForm::symmetric ? kernel_.get() : nullptr);
    exchangeGhosts(ps_, ps_.cloud.U);  // parallel
  }
  for (std::size_t a = 0; a < ps_.nMaterial; ++a) {
    ps_.cloud.positions[a] += 0.5 * dt * (oldU[a] + ps_.cloud.U[a]);
  }
}

void ProjectionSolver::findNeighbours(const Time& time) {
  const bool reorder = reorderDue();
  if (distributed_) {  // parallel: new ghosts; on reordering steps, migration (and repartition)
    auto t = timer_.scope("migration and ghosts");
    distributed_->beginStep(ps_, *materials_, kernel_->supportRadius(), reorder, time);
  }
  auto t = timer_.scope("neighbour search");
  if (reorder) {
    if (!distributed_) reorderMaterialParticles(ps_, kernel_->supportRadius());
    ppe_->renumbered();  // a kept AMG hierarchy (reuseSetup) is for the old numbering
    if (viscous_) viscous_->renumbered();
  }
  ps_.neighbours.build(ps_.cloud.positions, *kernel_);
}

void ProjectionSolver::correctKernels(StepReport& report) {
  auto t = timer_.scope("kernel and corrections");
  correction_.update(ps_, schemes_.kernelCorrection, schemes_.correctionMinDeterminant);
  freeSurface_->detect(ps_);
  report.freeSurface = freeSurface_->nSurfaceMaterial();
  walls_->prepare(freeSurface_->flags());
}

void ProjectionSolver::solvePressure(double dt, StepReport& report) {
  if (!lagged_.empty()) {  // the increment that the step applies to the predictor that saw pⁿ
    report.ppe = ppe_->solveIncrement(ps_, *kernel_, correction_, ustar_, freeSurface_->flags(), g_, dt, increment_);
  } else {
    report.ppe = ppe_->solve(ps_, *kernel_, correction_, ustar_, freeSurface_->flags(), g_, dt);
  }
  timer_.add("PPE assembly", ppe_->assemblySeconds() + report.ppe.assemblySeconds);
  timer_.add("PPE setup", report.ppe.setupSeconds);
  timer_.add("PPE solve", report.ppe.solveSeconds);
}

StepReport ProjectionSolver::step(const Time& time) {
  ++stepsTaken_;
  const double dt = time.deltaT();
  StepReport report;
  findNeighbours(time);
  // The pressure is the only particle field changed before the PPE has converged (positions
  // and velocities change after it): kept to restore the step start if a solve fails, for
  // the caller to redo the step (stepWithRetry).
  pStart_ = ps_.cloud.p;
  correctKernels(report);  // renormalisation, free surface, the walls' state
  intermediateVelocity(time, report);  // Eq. 6
  if (!report.viscous.empty() && report.failedSolve() != &report.ppe) {
    viscous_->renumbered();  // nothing has moved yet; a retry builds a fresh hierarchy for U
    ps_.cloud.p = pStart_;   // (the lagged pressure's smoothing may have changed it)
    return report;
  }
  solvePressure(dt, report);  // Eq. 10
  if (report.failedSolve()) {
    ps_.cloud.p = pStart_;
    return report;
  }
  if (lagged_.empty()) walls_->update(ustar_, dt);  // the walls' pressures of the step (p^{n+1})
  auto t = timer_.scope("velocity correction and shifting");
  correctAndMove(dt);  // Eq. 11, x^{n+1}
  finishStep(time, report);  // shifting, safeguards, domain
  return report;
}

}  // namespace isph
