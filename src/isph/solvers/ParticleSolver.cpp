#include "isph/solvers/ParticleSolver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Log.hpp"
#include "core/time/ProgressReporter.hpp"
#include "core/io/AtomicFile.hpp"
#include "isph/Gravity.hpp"
#include "isph/regularisation/ParticleCollision.hpp"
#include "isph/regularisation/ParticleShifting.hpp"
#include "isph/startup/StartupChecks.hpp"
#include "isph/walls/WallPenetrationGuard.hpp"
#include "isph/parallel/GhostExchange.hpp"
#include "isph/parallel/OwnedParticles.hpp"
#include "isph/parallel/StepStateOverRanks.hpp"
#include "parallel/DecomposedCase.hpp"
#include "parallel/Reduce.hpp"
#include "particles/CloudIO.hpp"

namespace isph {

namespace {

std::filesystem::path schemesFile(const Time& time) { return time.path() / "system" / "isphSchemes"; }

std::string findCloud(const std::filesystem::path& timeDir) {
  const std::vector<std::string> clouds = cloudNames(timeDir);
  if (clouds.size() != 1) {
    fatalError(fmt::format("expected one particle cloud in {}, found {}{}\n    (run particleMesh to create the "
                           "initial particles)",
                           (timeDir / "lagrangian").string(), clouds.size(),
                           clouds.empty() ? "" : ": " + fmt::format("{}", fmt::join(clouds, ", "))));
  }
  return clouds[0];
}

// A time a run wrote (it has uniform/) without the solver state: removed, or written before the
// state existed. The restart goes on from the particles, but not as the uninterrupted run would.
void warnRestartWithoutState(const Time& time) {
  const std::string message = fmt::format(
      "time {} has no solver state ({}/uniform/isphState is missing): the run restarts from the particles alone "
      "(the step counters, the previous step and the scene's scales start anew) and will not be bit-identical to "
      "an uninterrupted run",
      time.timeName(), time.timeName());
  warning(message);
  ProgressReporter::noteOnTerminal("--> Warning: " + message);
}

}  // namespace

std::unique_ptr<ParticleSolver> ParticleSolver::New(const Time& time, bool parallel) {
  const auto file = schemesFile(time);
  const Dictionary d = std::filesystem::exists(file) ? Dictionary::readFile(file) : Dictionary(file.string());
  const Entry* e = d.findEntry("method");
  return SolverRegistry::create(e ? d.get<std::string>("method") : std::string("isph"), "method",
                                e ? e->location() : d.location(), time, parallel);
}

ParticleSolver::ParticleSolver(const Time& time, bool parallel) {
  if (parallel) distributed_ = std::make_unique<DistributedParticles>(time);  // parallel: doc/parallel.md
  const std::string cloudName = findCloud(time.startPath());
  info("Reading cloud '{}' from {}", cloudName, time.timeName());
  ps_.cloud = distributed_ ? distributed_->read(time, cloudName) : readCloud(time.startPath(), cloudName);
  startCloudDir_ = time.startPath() / "lagrangian" / cloudName;
  writtenIds_ = ps_.cloud.origId;
  const int dim = ps_.cloud.properties.dimension;
  // What the run that wrote this time carried between its steps (StepState.hpp): a restart
  // takes it up, so that it continues as the uninterrupted run (parallel: the ranks' entries
  // gathered, as the particles are partitioned anew; StepStateOverRanks.hpp).
  state_ = distributed_ ? readStepStateOverRanks(time.startPath(), time.decomposedStart(), ps_.cloud.origId)
                        : readStepState(time.startPath());
  if (state_) info("    solver state (step {}) read from {}/uniform/isphState", state_->stepsTaken, time.timeName());
  if (!state_ && std::filesystem::exists(time.startPath() / "uniform")) warnRestartWithoutState(time);

  info("\nReading system/isphSchemes");
  schemesDict_ = Dictionary::readOptionalFile(schemesFile(time), "system/isphSchemes");
  kernel_ = makeKernel(schemesDict_, ps_.cloud.properties.spacing, dim);
  schemes_ = IsphSchemes::read(schemesDict_, dim);
  materials_ = std::make_unique<MaterialTable>(time.path() / "constant" / "materialProperties",
                                               ps_.cloud.properties.materials);
  g_ = readGravity(time.path());
  if (distributed_) {  // parallel: each rank's part, with the walls of its dummies
    if (schemes_.method == Method::wcsph) fatalError("method wcsph does not run in parallel (it runs on one rank)");
    distributed_->distribute(ps_.cloud, 2.0 * kernel_->supportRadius());
  }
  initialiseParticleSystem(ps_, *materials_, *kernel_);
  if (distributed_) distributed_->beginStep(ps_, *materials_, kernel_->supportRadius(), false, time);  // parallel: ghosts
  setSceneScales(state_ ? &state_->materialHeights : nullptr);
  viscousStress_ = std::make_unique<ViscousStress>(ps_, *materials_, correction_, schemes_.correctionMinDeterminant);

  const double slipSpeed =
      schemes_.frictionSlipSpeed > 0 ? schemes_.frictionSlipSpeed : 1e-4 * std::sqrt(g_.norm() * ps_.dx);
  friction_ = std::make_unique<WallFriction>(ps_, *materials_, g_, slipSpeed, schemes_.frictionNormal);
  walls_ = std::make_unique<WallBoundary>(ps_, *materials_, g_, schemes_.correctionMinDeterminant,
                                          friction_->slidingMaterial());
  if (friction_->active()) wallFriction_.assign(ps_.size(), Vec3::Zero());  // (none before the first step)
  markFrictionWalls(ps_);
  // A case from particleMesh has no wall pressures yet (a restart has them).
  freshStart_ = allRanks(std::all_of(ps_.cloud.p.begin() + static_cast<long>(ps_.wallBegin()), ps_.cloud.p.end(),
                                     [](double v) { return v == 0.0; }));  // parallel: all ranks
  if (state_) freshStart_ = false;
  initialiseWallPressure();

  freeSurface_ = std::make_unique<FreeSurfaceDetector>(
      schemes_.freeSurfaceThreshold, schemes_.freeSurfaceGradient, schemes_.minNeighbourFraction,
      fullLatticeNeighbourCount(*kernel_, ps_.dx, ps_.cloud.properties.lattice, dim), kernel_->h());
  // The domain the particles must stay in; a restart's particles are checked against it.
  domain_ = startDomain(time, cloudName, ps_,
                        state_ ? std::optional(SceneDomain{state_->domainMin, state_->domainMax}) : std::nullopt);
  checkMaterialSideOfWalls(ps_, startCloudDir_);   // material behind a wall, named
  checkSpeeds(ps_, domain_, g_, startCloudDir_);  // a hand-edited or blown-up U, named
}

ParticleSolver::~ParticleSolver() = default;

void ParticleSolver::finishConstruction() {
  if (state_) {
    stepsTaken_ = state_->stepsTaken;
    stepsSinceReorder_ = state_->stepsSinceReorder;
    freshStart_ = state_->freshStart;
    viscousStress_->restore(state_->viscosityKnown, state_->maxNu);
    maxViscousAcceleration_ = state_->maxViscousAcceleration;
    restoreMethodState(*state_);
  }
  state_.reset();      // (read at start only: the restart's per-particle entries, and the
  writtenIds_ = {};    // order in which its fields were written)
  info("\nActive models and schemes");
  const std::size_t nMaterial = sumOverRanks(ps_.ownMaterial()), nWall = sumOverRanks(ps_.ownWall()),
                    nDummy = sumOverRanks(ps_.ownDummy());  // parallel: all ranks'
  nMaterialAll_ = nMaterial;
  info("    {}D, {} particles: {} material, {} wall, {} dummy; dx = {} m, kernel {} with h = {} m ({:.4g} dx)",
       ps_.cloud.properties.dimension, nMaterial + nWall + nDummy, nMaterial, nWall, nDummy, ps_.dx, kernel_->name(),
       kernel_->h(), kernel_->h() / ps_.dx);
  for (std::size_t i = 0; i < materials_->size(); ++i) info("    material {}", (*materials_)[i].describe());
  for (const auto& p : ps_.cloud.properties.patches) {
    info("    wall patch {}: no penetration ({}); fluids stick; granular material {}", p.name, wallCondition(),
         p.frictionAngle > 0 && friction_->active()
             ? fmt::format("slides with Coulomb friction, angle {} deg (tan = {:.4g}), sticking below {:.3g} m/s",
                           p.frictionAngle, std::tan(p.frictionAngle * std::numbers::pi / 180.0), friction_->slipSpeed())
             : "slides freely (no friction angle)");
  }
  info("    gravity ({} {} {}) m/s^2", g_.x(), g_.y(), g_.z());
  infoLine(schemes_.describe() + describeStages());
  schemesDict_.checkKeywords();  // (the stages have read theirs)
}

StepState ParticleSolver::currentState() const {
  StepState s;
  s.stepsTaken = stepsTaken_;
  s.stepsSinceReorder = stepsSinceReorder_;
  s.freshStart = freshStart_;
  s.viscosityKnown = viscousStress_->known();
  s.maxNu = viscousStress_->maxNu();
  s.maxViscousAcceleration = maxViscousAcceleration_;
  s.domainMin = domain_.min;
  s.domainMax = domain_.max;
  s.materialHeights = sceneHeights_;
  saveMethodState(s);
  return s;
}

void ParticleSolver::setSceneScales(const std::vector<double>* heights) {
  // Each material's height along gravity (its extent if there is no gravity); a restart
  // takes those of the first start (the solver state), not those of the moved material.
  const Vec3 up = g_.norm() > 0 ? Vec3(-g_ / g_.norm()) : Vec3::UnitY();
  sceneHeights_.assign(materials_->size(), 0.0);
  for (std::size_t m = 0; m < materials_->size(); ++m) {
    double lo = 1e300, hi = -1e300;
    for (std::size_t a = 0; a < ps_.nMaterial; ++a) {
      if (static_cast<std::size_t>(ps_.cloud.material[a]) != m) continue;
      lo = std::min(lo, up.dot(ps_.cloud.positions[a]));
      hi = std::max(hi, up.dot(ps_.cloud.positions[a]));
    }
    lo = minOverRanks(lo), hi = maxOverRanks(hi);  // parallel: all ranks
    double height = hi > lo ? hi - lo + ps_.dx : ps_.dx;
    if (heights && heights->size() == materials_->size()) height = (*heights)[m];
    sceneHeights_[m] = height;
    (*materials_)[m].adaptToScene({.height = height, .gravity = g_.norm(), .spacing = ps_.dx});
  }
}

void ParticleSolver::initialiseWallPressure() {
  // A case from particleMesh has no wall pressures yet (a restart has them): the walls take
  // the pressure of material at rest against them, so that the first step has wall friction.
  const auto& p = ps_.cloud.p;
  if (!friction_->active() || anyRank(std::any_of(p.begin() + static_cast<long>(ps_.wallBegin()), p.end(),
                                                  [](double v) { return v != 0.0; }))) {  // parallel: all ranks
    return;
  }
  std::vector<Vec3> atRest(ps_.size(), Vec3::Zero());
  for (std::size_t a = 0; a < ps_.nMaterial; ++a) atRest[a] = ps_.cloud.U[a] + g_;  // u* = u + g dt, dt = 1
  walls_->settle(*kernel_, atRest);
}

const std::vector<SymmTensor>* ParticleSolver::deviatoricStress() { return viscousStress_->tau(stepsTaken_); }

const std::vector<Vec3>* ParticleSolver::wallFriction() const {
  return friction_->active() ? &wallFriction_ : nullptr;
}

std::string ParticleSolver::safeguardSummary() const {
  const auto per10k = [&](std::size_t n) {
    return materialParticleSteps_ > 0 ? 1e4 * static_cast<double>(n) / materialParticleSteps_ : 0.0;
  };
  return fmt::format("Wall safeguard in the run: {} particle-steps ({:.3g} per 10,000 material particle-steps)\n"
                     "Collision separation in the run: {} particle-steps ({:.3g} per 10,000 material particle-steps)",
                     totalSafeguard_, per10k(totalSafeguard_), totalCollisions_, per10k(totalCollisions_));
}

TimeStepLimits ParticleSolver::nextDeltaT(const Time& time) const {
  double maxSpeed = 0;
  for (std::size_t a = 0; a < ps_.ownMaterial(); ++a) maxSpeed = std::max(maxSpeed, ps_.cloud.U[a].norm());
  maxSpeed = maxOverRanks(maxSpeed);  // parallel: all ranks
  // The explicit deviatoric term is stable below dt ≤ C_ν ρ h²/η: the largest η/ρ of the
  // last step (the models' bound before the first); the implicit step has no such limit.
  double maxNu = 0;
  if (explicitDeviatoricTerm()) {
    if (!viscousStress_->known()) {
      for (std::size_t i = 0; i < materials_->size(); ++i) {
        maxNu = std::max(maxNu, (*materials_)[i].maxViscosity() / (*materials_)[i].rho());
      }
    } else {
      maxNu = viscousStress_->maxNu();
    }
  }
  const MethodScales scales = methodScales();  // e.g. the acoustic Courant limit
  const double force = std::max(g_.norm() + maxViscousAcceleration_, scales.acceleration);
  const double previous = time.timeIndex() > 0 ? time.deltaT() : 0.0;
  return timeStepLimits(kernel_->h(), maxSpeed + scales.signalSpeed, time.settings().maxCo, force,
                        schemes_.forceFactor, maxNu, schemes_.viscousFactor, previous, schemes_.maxGrowth,
                        time.settings().maxDeltaT);
}

void ParticleSolver::finishStep(const Time& time, StepReport& report) {
  const double dt = time.deltaT();
  if (schemes_.shifting.enabled) {
    report.maxShift = shiftParticles(ps_, *kernel_, freeSurface_->flags(), schemes_.shifting,
                                     schemes_.correctionMinDeterminant, schemes_.tensionCutoff, dt)
                          .maxShift;
  }
  report.collisions = separateCloseParticles(ps_, schemes_.collisionDistance).moved;
  const WallGuardResult guard = guardWallPenetration(ps_, schemes_.wallSafeguardDistance);
  report.wallSafeguard = guard.moved;
  report.wallCrossings = guard.crossed;
  if (guard.crossed > 0 && totalWallCrossings_ == 0) {
    warning(fmt::format("first wall crossing at time {}: {} ({} particle(s) this step)", time.timeName(),
                        guard.firstCrossing, guard.crossed));
  }
  totalWallCrossings_ += guard.crossed;
  totalSafeguard_ += guard.moved;
  totalCollisions_ += report.collisions;
  materialParticleSteps_ += static_cast<double>(nMaterialAll_);
  for (std::size_t a = 0; a < ps_.ownMaterial(); ++a) report.maxSpeed = std::max(report.maxSpeed, ps_.cloud.U[a].norm());
  report.maxSpeed = maxOverRanks(report.maxSpeed);  // parallel: all ranks
  report.courant = report.maxSpeed * dt / kernel_->h();
  checkStillInDomain(ps_, domain_, time);
}

void ParticleSolver::writeMethodFields(const std::filesystem::path& cloudDir, const FieldWriteOptions& options) const {
  (void)cloudDir, (void)options;
}

void ParticleSolver::write(Time& time) {
  auto t = timer_.scope("output");
  StagedDirectory dir(time.timePath());  // (parallel: processor<rank>/<time>, the own particles)
  FieldWriteOptions options{time.settings().writeFormat, time.settings().writePrecision, ""};
  writeCloud(dir.path(), time.timeName(), distributed_ ? ownedCloud(ps_) : ps_.cloud, options);
  const auto cloudDir = dir.path() / "lagrangian" / ps_.cloud.name;
  std::vector<label> flags(freeSurface_->flags().begin(), freeSurface_->flags().end());
  flags.resize(ps_.size(), 0);
  options.location = fmt::format("{}/lagrangian/{}", time.timeName(), ps_.cloud.name);
  writeField(cloudDir / "freeSurface", ownedValues(ps_, flags), options);
  if (const auto* tau = deviatoricStress()) writeField(cloudDir / "tau", ownedValues(ps_, *tau), options);
  if (const auto* friction = wallFriction()) writeField(cloudDir / "wallFriction", ownedValues(ps_, *friction), options);
  writeMethodFields(cloudDir, options);
  writeStepState(dir.path(), currentState(), options.format);
  time.writeTimeState(dir.path());
  dir.commit();
  time.purgeOldWrites();
  afterWrite();
}

}  // namespace isph
