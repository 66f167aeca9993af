#include "isph/solvers/ProjectionSolver.hpp"

#include <fmt/format.h>

#include <chrono>

#include "core/Log.hpp"
#include "isph/parallel/OwnedParticles.hpp"
#include "isph/deviatoric/ElasticPlasticStress.hpp"

namespace isph {

namespace {

const bool registered = SolverRegistry::add(
    "isph", [](const Time& time, bool parallel) { return std::make_unique<ProjectionSolver>(time, parallel); });

}  // namespace

ProjectionSolver::ProjectionSolver(const Time& time, bool parallel)
    : ParticleSolver(time, parallel),
      context_{ps_,      *materials_, *kernel_,        correction_, *freeSurface_, *walls_,
               *friction_, *viscousStress_, timer_, g_,           wallFriction_} {
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
  const StageSetup setup{schemesDict_, solution, schemes_, *materials_, ps_.cloud.properties.dimension};
  deviatoric_ = DeviatoricTerm::New(setup);
  projection_ = Projection::New(setup);
  solution.checkKeywords({"U"});
  finishConstruction();
}

void ProjectionSolver::afterWrite() {
  ppe_->renumbered();
  deviatoric_->renumbered();
}

std::string ProjectionSolver::preconditionerSummary() const {
  std::string s = fmt::format("AMG hierarchies built for p: {} of {} solves", ppe_->solver().preconditionersBuilt(),
                              ppe_->solver().solvesDone());
  const std::string u = deviatoric_->summary();
  return u.empty() ? s : s + "\n" + u;
}

void ProjectionSolver::intermediateVelocity(const Time& time, StepReport& report) {
  const double dt = time.deltaT();
  {
    auto t = timer_.scope("rheology");
    viscousStress_->update();
    friction_->update(ps_);
  }
  maxViscousAcceleration_ = deviatoric_->predict(context_, dt, stepsTaken_, ustar_, report);
}

void ProjectionSolver::solvePressure(double dt, StepReport& report) {
  const auto start = std::chrono::steady_clock::now();
  report.ppe = projection_->solvePressure(context_, *ppe_, ustar_, dt);
  const SolverPerformance& p = report.ppe;
  timer_.add("PPE assembly", ppe_->assemblySeconds() + p.assemblySeconds);
  timer_.add("PPE setup", p.setupSeconds);
  timer_.add("PPE solve", p.solveSeconds);
  timer_.add("PPE checks", p.checkSeconds);
  // (the Dirichlet rows' pressures, the solution handed back, the wall pressures)
  timer_.add("PPE other",
             std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - ppe_->assemblySeconds() -
                 p.seconds());
}

void ProjectionSolver::correctAndMove(double dt) {
  std::vector<Vec3> oldU(ps_.cloud.U.begin(), ps_.cloud.U.begin() + static_cast<long>(ps_.nMaterial));
  projection_->correct(context_, ustar_, dt);
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
    deviatoric_->renumbered();
  }
  // Walls: their material neighbours; ghosts (parallel): no row of their own.
  const std::vector<char> owned = distributed_ ? ownedMask(ps_) : std::vector<char>();
  ps_.neighbours.build(ps_.cloud.positions, *kernel_, ps_.nMaterial, distributed_ ? &owned : nullptr);
}

void ProjectionSolver::correctKernels(StepReport& report) {
  auto t = timer_.scope("kernel and corrections");
  correction_.update(ps_, schemes_.kernelCorrection, schemes_.correctionMinDeterminant);
  freeSurface_->detect(ps_);
  report.freeSurface = freeSurface_->nSurfaceMaterial();
  walls_->prepare(freeSurface_->flags());
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
    deviatoric_->renumbered();  // nothing has moved yet; a retry builds a fresh hierarchy for U
    ps_.cloud.p = pStart_;
    return report;
  }
  solvePressure(dt, report);  // Eq. 10
  if (report.failedSolve()) {
    ps_.cloud.p = pStart_;
    return report;
  }
  auto t = timer_.scope("velocity correction and shifting");
  correctAndMove(dt);  // Eq. 11 and the walls' pressures of the step, x^{n+1}
  finishStep(time, report);  // shifting, safeguards, domain
  return report;
}

}  // namespace isph
