#include "isph/IsphSolver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <unordered_map>

#include "core/Log.hpp"
#include "core/fields/FieldIO.hpp"
#include "core/io/AtomicFile.hpp"
#include "isph/EffectiveViscosity.hpp"
#include "isph/Gravity.hpp"
#include "isph/MaterialGradient.hpp"
#include "isph/StepState.hpp"
#include "isph/StartupChecks.hpp"
#include "isph/WallBoundaryPressure.hpp"
#include "isph/IntermediateVelocity.hpp"
#include "isph/LaggedPressure.hpp"
#include "isph/ParticleCollision.hpp"
#include "isph/ParticleShifting.hpp"
#include "isph/VelocityCorrection.hpp"
#include "isph/WallPenetrationGuard.hpp"
#include "isph/materials/DruckerPragerElasticPlastic.hpp"
#include "isph/parallel/GhostExchange.hpp"
#include "isph/parallel/StepStateOverRanks.hpp"
#include "parallel/Reduce.hpp"
#include "particles/CloudIO.hpp"

namespace isph {

namespace {

constexpr long reorderInterval = 50;  // steps between cell reorderings of the material particles

Dictionary readOptional(const std::filesystem::path& file, const std::string& name) {
  if (std::filesystem::exists(file)) return Dictionary::readFile(file);
  info("    {} not found: using the defaults", name);
  return Dictionary(file.string());
}

std::string findCloud(const std::filesystem::path& timeDir) {
  const auto dir = timeDir / "lagrangian";
  std::vector<std::string> clouds;
  if (std::filesystem::is_directory(dir)) {
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
      if (e.is_directory() && e.path().filename().string()[0] != '.') clouds.push_back(e.path().filename().string());
    }
  }
  std::sort(clouds.begin(), clouds.end());
  if (clouds.size() != 1) {
    fatalError(fmt::format("expected one particle cloud in {}, found {}{}\n    (run particleMesh to create the "
                           "initial particles)",
                           dir.string(), clouds.size(), clouds.empty() ? "" : ": " + fmt::format("{}", fmt::join(clouds, ", "))));
  }
  return clouds[0];
}

// The largest sound speed √(K/ρ) and P-wave speed of the elasticPlastic materials (0: none).
// FatalError if such a material is not alone in the scene or runs with the projection method.
std::pair<double, double> elasticPlasticSpeeds(const MaterialTable& materials, Method method) {
  double sound = 0, wave = 0;
  std::size_t elastic = 0;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    if (!materials[i].integratesStress()) continue;
    ++elastic;
    const auto& m = static_cast<const DruckerPragerElasticPlastic&>(materials[i]);
    sound = std::max(sound, m.bulkSpeed());
    wave = std::max(wave, m.waveSpeed());
  }
  if (elastic > 0 && (method != Method::wcsph || elastic != materials.size())) {
    fatalError(fmt::format("constant/materialProperties: model elasticPlastic runs with `method wcsph;` in "
                           "system/isphSchemes and with no other model in the scene; found {} of {} materials "
                           "elasticPlastic{}",
                           elastic, materials.size(), method != Method::wcsph ? " and the projection method" : ""));
  }
  return {sound, wave};
}

// A field read in the order of `writtenIds`, put into the order of `ids` (the cloud is
// reordered after reading).
template <class T>
std::vector<T> inOrderOf(const std::vector<label>& ids, const std::vector<T>& written,
                         const std::vector<label>& writtenIds) {
  std::unordered_map<label, std::size_t> at;
  for (std::size_t i = 0; i < writtenIds.size(); ++i) at[writtenIds[i]] = i;
  std::vector<T> out(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) out[i] = written[at.at(ids[i])];
  return out;
}

}  // namespace

IsphSolver::IsphSolver(const Time& time, bool parallel) {
  if (parallel) distributed_ = std::make_unique<DistributedParticles>(time);  // parallel: doc/parallel.md
  const auto& caseDir = time.path();
  const std::string cloudName = findCloud(time.startPath());
  info("Reading cloud '{}' from {}", cloudName, time.timeName());
  ps_.cloud = distributed_ ? distributed_->read(time, cloudName) : readCloud(time.startPath(), cloudName);
  const int dim = ps_.cloud.properties.dimension;
  // What the run that wrote this time carried between its steps (StepState.hpp): a restart
  // takes it up, so that it continues as the uninterrupted run (parallel: the ranks' entries
  // gathered, as the particles are partitioned anew; StepStateOverRanks.hpp).
  const std::optional<StepState> state =
      distributed_ ? readStepStateOverRanks(time.startPath(), time.decomposedStart(), ps_.cloud.origId)
                   : readStepState(time.startPath());
  if (state) info("    solver state (step {}) read from {}/uniform/isphState", state->stepsTaken, time.timeName());
  // The state of a weakly-compressible run beside p, in the order read: the densities, and
  // the deviatoric stress of an elastic-plastic material (its tau). The cloud is reordered below.
  const std::vector<label> writtenIds = ps_.cloud.origId;
  const auto fieldFile = [&](const char* name) { return time.startPath() / "lagrangian" / cloudName / name; };
  std::vector<scalar> writtenDensity;
  if (std::filesystem::is_regular_file(fieldFile("rho"))) {
    writtenDensity = readField<scalar>(fieldFile("rho"), writtenIds.size());
  }

  info("\nReading system/isphSchemes");
  schemes_ = IsphSchemes::read(readOptional(caseDir / "system" / "isphSchemes", "system/isphSchemes"), dim);
  materials_ = std::make_unique<MaterialTable>(caseDir / "constant" / "materialProperties",
                                               ps_.cloud.properties.materials);
  g_ = readGravity(caseDir);
  kernel_ = makeKernel(schemes_.kernel, schemes_.hOverDx * ps_.cloud.properties.spacing, dim);
  if (distributed_) {  // parallel: each rank's part, with the walls of its dummies
    if (schemes_.method == Method::wcsph) fatalError("method wcsph does not run in parallel (it runs on one rank)");
    distributed_->distribute(ps_.cloud, 2.0 * kernel_->supportRadius());
  }
  initialiseParticleSystem(ps_, *materials_, *kernel_);
  if (distributed_) distributed_->beginStep(ps_, *materials_, kernel_->supportRadius(), false, time);  // parallel: ghosts
  setSceneScales(state ? &state->materialHeights : nullptr);

  info("\nReading system/isphSolution");
  const Dictionary solution = readOptional(caseDir / "system" / "isphSolution", "system/isphSolution");
  std::vector<char> keepCompressed(materials_->size(), 0);
  for (std::size_t i = 0; i < materials_->size(); ++i) {
    keepCompressed[i] = schemes_.compressedSurface == CompressedSurface::all ||
                        (schemes_.compressedSurface == CompressedSurface::granular &&
                         (*materials_)[i].wallContact() == WallContact::coulombFriction);
  }
  ppe_ = std::make_unique<PressurePoissonEquation>(schemes_, makeLinearSolver(solution.subDictOrEmpty("p"), "p"),
                                                   std::move(keepCompressed));
  if (materials_->anyDeviatoricStress() && schemes_.viscousTerm == ViscousTerm::implicit) {
    viscous_ = std::make_unique<ImplicitViscousStep>(solution.subDictOrEmpty("U"), dim, schemes_.frictionPasses);
    bool granular = false;
    for (std::size_t i = 0; i < materials_->size(); ++i) {
      granular = granular || (*materials_)[i].wallContact() == WallContact::coulombFriction;
    }
    incremental_ = schemes_.incrementalPressure == MaterialScope::all ||
                   (schemes_.incrementalPressure == MaterialScope::granular && granular);
  }
  solution.checkKeywords({"U"});
  if (schemes_.frictionSlipSpeed < 0) schemes_.frictionSlipSpeed = 1e-4 * std::sqrt(g_.norm() * ps_.dx);
  friction_ = std::make_unique<WallFriction>(ps_, *materials_, g_, schemes_.frictionSlipSpeed, schemes_.frictionNormal);
  if (friction_->active()) wallFriction_.assign(ps_.size(), Vec3::Zero());  // (none before the first step)
  markFrictionWalls(ps_);
  // A case from particleMesh has no wall pressures yet (a restart has them): its first step
  // is a plain projection, whose pressure the incremental projection then carries on.
  freshStart_ = allRanks(std::all_of(ps_.cloud.p.begin() + static_cast<long>(ps_.wallBegin()), ps_.cloud.p.end(),
                                     [](double v) { return v == 0.0; }));  // parallel: all ranks
  if (state) freshStart_ = false;
  initialiseWallPressure();
  const auto [elasticSound, elasticWave] = elasticPlasticSpeeds(*materials_, schemes_.method);
  waveSpeed_ = elasticWave;
  if (schemes_.method == Method::wcsph) {
    if (schemes_.soundSpeed <= 0 && state && state->soundSpeed > 0) schemes_.soundSpeed = state->soundSpeed;
    if (schemes_.soundSpeed <= 0 && elasticSound > 0) schemes_.soundSpeed = elasticSound;  // p = K (ρ − ρ0)/ρ0
    if (schemes_.soundSpeed <= 0) schemes_.soundSpeed = defaultSoundSpeed(ps_, g_);
    if (!(schemes_.soundSpeed > 0)) {
      fatalError("method wcsph: a scene at rest without gravity has no speed scale for the default sound speed; "
                 "give one in system/isphSchemes, e.g. wcsph { soundSpeed 20; }");
    }
    wcsph_ = std::make_unique<WeaklyCompressibleStep>(schemes_, schemes_.soundSpeed);
    if (freshStart_) {  // the walls' densities from the hydrostatic extrapolation of the material's pressure
      ps_.neighbours.build(ps_.cloud.positions, *kernel_);
      prepareWallPressure(std::vector<char>(ps_.nMaterial, 0));
      std::vector<Vec3> atRest(ps_.nMaterial, g_);  // u* = g dt with dt = 1
      updateWallPressure(ps_, atRest, g_, 1.0);
    }
    if (!writtenDensity.empty()) {  // a restart of a weakly-compressible run
      wcsph_->setDensity(inOrderOf(ps_.cloud.origId, writtenDensity, writtenIds));
      info("    densities of the weakly-compressible state read from {}", time.timeName());
    } else {
      wcsph_->initialiseDensity(ps_);
    }
    if (elasticWave > 0) {  // elasticPlastic: s is the state, written as tau (ElasticPlasticStress.hpp)
      elastic_ = std::make_unique<ElasticPlasticStress>();
      if (std::filesystem::is_regular_file(fieldFile("tau"))) {
        const auto written = readField<SymmTensor>(fieldFile("tau"), writtenIds.size());
        const std::vector<SymmTensor> tau = inOrderOf(ps_.cloud.origId, written, writtenIds);
        elastic_->initialise(ps_, &tau);
        info("    deviatoric stresses of the elastic-plastic state read from {}", time.timeName());
      } else {
        elastic_->initialise(ps_, nullptr);
      }
    }
  }

  freeSurface_ = std::make_unique<FreeSurfaceDetector>(
      schemes_.freeSurfaceThreshold, schemes_.freeSurfaceGradient, schemes_.minNeighbourFraction,
      fullLatticeNeighbourCount(*kernel_, ps_.dx, ps_.cloud.properties.lattice, dim), kernel_->h());

  // The domain the particles must stay in; a restart's particles are checked against it.
  const SceneDomain domain =
      startDomain(time, cloudName, ps_, state ? std::optional(SceneDomain{state->domainMin, state->domainMax}) : std::nullopt);
  domainMin_ = domain.min;
  domainMax_ = domain.max;
  if (state) restoreState(*state);

  info("\nActive models and schemes");
  const std::size_t nMaterial = sumOverRanks(ps_.ownMaterial()), nWall = sumOverRanks(ps_.ownWall()),
                    nDummy = sumOverRanks(ps_.ownDummy());  // parallel: all ranks'
  nMaterialAll_ = nMaterial;
  info("    {}D, {} particles: {} material, {} wall, {} dummy; dx = {} m, h = {} m", dim, nMaterial + nWall + nDummy,
       nMaterial, nWall, nDummy, ps_.dx, kernel_->h());
  for (std::size_t i = 0; i < materials_->size(); ++i) info("    material {}", (*materials_)[i].describe());
  for (const auto& p : ps_.cloud.properties.patches) {
    info("    wall patch {}: no penetration ({}); fluids stick; granular material {}", p.name,
         wcsph_ ? "dynamic boundary particles" : "Neumann wall pressure",
         p.frictionAngle > 0 && friction_->active()
             ? fmt::format("slides with Coulomb friction, angle {} deg (tan = {:.4g}), sticking below {:.3g} m/s",
                           p.frictionAngle, std::tan(p.frictionAngle * std::numbers::pi / 180.0), schemes_.frictionSlipSpeed)
             : "slides freely (no friction angle)");
  }
  info("    gravity ({} {} {}) m/s^2", g_.x(), g_.y(), g_.z());
  infoLine(schemes_.describe());
}

IsphSolver::~IsphSolver() = default;

StepState IsphSolver::currentState() const {
  StepState s;
  s.stepsTaken = stepsTaken_;
  s.stepsSinceReorder = stepsSinceReorder_;
  s.freshStart = freshStart_;
  s.viscosityKnown = !eta_.empty();
  s.maxNu = maxNu_;
  s.maxViscousAcceleration = maxViscousAcceleration_;
  s.maxAcceleration = maxAcceleration_;
  s.soundSpeed = wcsph_ ? wcsph_->soundSpeed() : 0.0;
  s.domainMin = domainMin_;
  s.domainMax = domainMax_;
  s.materialHeights = sceneHeights_;
  if (viscous_) viscous_->saveState(s);
  return s;
}

void IsphSolver::restoreState(const StepState& s) {
  stepsTaken_ = s.stepsTaken;
  stepsSinceReorder_ = s.stepsSinceReorder;
  freshStart_ = s.freshStart;
  maxNu_ = s.maxNu;
  // Only whether η exists matters before the next step computes it (nextDeltaT's explicit limit).
  if (s.viscosityKnown) eta_.assign(ps_.nMaterial, 0.0);
  maxViscousAcceleration_ = s.maxViscousAcceleration;
  maxAcceleration_ = s.maxAcceleration;
  if (viscous_) viscous_->restoreState(s);
}

void IsphSolver::setSceneScales(const std::vector<double>* heights) {
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

void IsphSolver::prepareWallPressure(const std::vector<char>& surface) {
  ps_.wallPullLimit.assign(ps_.size(), 0.0);
  for (std::size_t a = 0; a < ps_.nMaterial; ++a) {
    ps_.wallPullLimit[a] = surface[a] ? 0.0 : std::max(ps_.cloud.p[a], 0.0);
  }
  ps_.wallTangentialGradient.assign(ps_.nMaterial, Vec3::Zero());
  const std::vector<Vec3> gradP = friction_->slidingMaterial()
                                      ? materialPressureGradient(ps_, schemes_.correctionMinDeterminant)
                                      : std::vector<Vec3>();
  for (std::size_t a = 0; a < ps_.nMaterial; ++a) {
    const bool slides = (*materials_)[static_cast<std::size_t>(ps_.cloud.material[a])].wallContact() ==
                        WallContact::coulombFriction;
    ps_.wallTangentialGradient[a] = slides ? gradP[a] : Vec3(ps_.rho[a] * g_);
  }
  exchangeGhosts(ps_, ps_.wallTangentialGradient);  // parallel: the wall pressure reads it at ghosts
}

void IsphSolver::initialiseWallPressure() {
  // A case from particleMesh has no wall pressures yet (a restart has them): the walls take
  // the pressure of material at rest against them, so that the first step has wall friction.
  const auto& p = ps_.cloud.p;
  if (!friction_->active() || anyRank(std::any_of(p.begin() + static_cast<long>(ps_.wallBegin()), p.end(),
                                                  [](double v) { return v != 0.0; }))) {  // parallel: all ranks
    return;
  }
  ps_.neighbours.build(ps_.cloud.positions, *kernel_);
  prepareWallPressure(std::vector<char>(ps_.nMaterial, 0));
  std::vector<Vec3> atRest(ps_.size(), Vec3::Zero());
  for (std::size_t a = 0; a < ps_.nMaterial; ++a) atRest[a] = ps_.cloud.U[a] + g_;  // u* = u + g dt, dt = 1
  updateWallPressure(ps_, atRest, g_, 1.0);
}

std::string IsphSolver::preconditionerSummary() const {
  std::string s;
  if (ppe_) {
    s += fmt::format("AMG hierarchies built for p: {} of {} solves", ppe_->solver().preconditionersBuilt(),
                     ppe_->solver().solvesDone());
  }
  if (viscous_) {
    s += fmt::format("{}AMG hierarchies built for U: {} of {} solves", s.empty() ? "" : "\n",
                     viscous_->preconditionersBuilt(), viscous_->solvesDone());
    if (viscous_->frictionSolves() > 0) {
      s += fmt::format("\nBed friction: stick/slip states settled in {} of {} steps ({:.2f} passes per step, at most {})",
                       viscous_->frictionSolvesSettled(), viscous_->frictionSolves(),
                       static_cast<double>(viscous_->frictionPassesDone()) / viscous_->frictionSolves(),
                       viscous_->maxFrictionPasses());
    }
  }
  return s;
}

const std::vector<SymmTensor>* IsphSolver::deviatoricStress() {
  if (!materials_->anyDeviatoricStress()) return nullptr;
  if (elastic_) return &elastic_->deviatoric();  // the state: s after the last step, or read
  if (tauStep_ != stepsTaken_) {
    // No step taken yet (the start time): τ = 2 η D of the state read, as the first step's
    // predictor will see it. (The time step must not depend on whether a write asked: the
    // viscous limit keeps the η it had.)
    const double maxNu = maxNu_;
    updateRheology();
    maxNu_ = maxNu;
    tau_ = isph::deviatoricStress(ps_, strain_, eta_);
    tauStep_ = stepsTaken_;
  }
  return &tau_;
}

void IsphSolver::keepActingStress(const std::vector<Vec3>* ustar) {
  // The deviatoric stress that entered the step's momentum balance: the viscosity of time n
  // with the strain rate of the velocity it acted on, u* for the semi-implicit term (Eq. 6
  // solved for u*), uⁿ for the explicit one. This is what is written and what a wall force
  // integrates, not a stress re-evaluated from the corrected velocity (which carries the
  // projection's splitting error as a strain rate that no stress resisted).
  if (!materials_->anyDeviatoricStress()) return;
  if (ustar) {
    StrainRate acting;
    acting.compute(ps_, *materials_, correction_, schemes_.correctionMinDeterminant, *ustar);
    tau_ = isph::deviatoricStress(ps_, acting, eta_);
  } else {
    tau_ = isph::deviatoricStress(ps_, strain_, eta_);
  }
  tauStep_ = stepsTaken_;
}

void IsphSolver::updateRheology() {
  if (!materials_->anyDeviatoricStress()) {
    eta_.clear();
    return;
  }
  strain_.compute(ps_, *materials_, correction_, schemes_.correctionMinDeterminant);
  maxNu_ = effectiveViscosity(ps_, *materials_, strain_, eta_);
}

void IsphSolver::intermediateVelocity(const Time& time, StepReport& report) {
  const double dt = time.deltaT();
  {
    auto t = timer_.scope("rheology");
    updateRheology();
    // The incremental projection (see the header): the viscous solve sees the pressure force
    // of the last step, −∇pⁿ/ρ (the walls' condition of a material at rest, ũ = uⁿ + dt g).
    lagged_.clear();
    std::vector<Vec3> reaction;
    if (incrementalNow()) {
      lagged_.resize(ps_.nMaterial);
      std::vector<Vec3> resting(ps_.cloud.U);
      for (std::size_t a = 0; a < ps_.nMaterial; ++a) resting[a] += dt * g_;
      const long n = static_cast<long>(ps_.nMaterial);
      if (schemes_.laggedForm == LaggedPressureForm::gradient) {
        // The gradient of Eq. 11 of p̃ (LaggedPressure.hpp); the PPE then solves for p^{n+1} − p̃.
        if (schemes_.laggedSmoothing > 0) {
          const std::vector<double> smooth =
              smoothedPressure(ps_, *kernel_, freeSurface_->flags(), schemes_.laggedSmoothing);
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
    friction_->update(ps_, reaction.empty() ? nullptr : &reaction);
  }
  if (viscous_) {
    const auto perf = viscous_->solve(ps_, *materials_, eta_, friction_.get(), g_, dt, kernel_->h(), lagged_, ustar_);
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
    keepActingStress(&ustar_);  // u* with its ghosts (exchanged above)
    return;
  }
  auto t = timer_.scope("intermediate velocity");
  keepActingStress(nullptr);
  maxViscousAcceleration_ = IntermediateVelocity::compute(ps_, *materials_, eta_, g_, dt, kernel_->h(), ustar_);
  applyExplicitFriction(dt);
  exchangeGhosts(ps_, ustar_);  // parallel
}

void IsphSolver::applyExplicitFriction(double dt) {
  if (!friction_->active()) return;
  std::vector<Vec3> applied;
  friction_->applyExplicit(ps_, dt, ustar_, &applied);
  exchangeGhosts(ps_, applied);  // parallel
  wallFriction_ = friction_->wallTraction(ps_, applied);
}

std::string IsphSolver::safeguardSummary() const {
  const auto per10k = [&](std::size_t n) {
    return materialParticleSteps_ > 0 ? 1e4 * static_cast<double>(n) / materialParticleSteps_ : 0.0;
  };
  return fmt::format("Wall safeguard in the run: {} particle-steps ({:.3g} per 10,000 material particle-steps)\n"
                     "Collision separation in the run: {} particle-steps ({:.3g} per 10,000 material particle-steps)",
                     totalSafeguard_, per10k(totalSafeguard_), totalCollisions_, per10k(totalCollisions_));
}

const std::vector<Vec3>* IsphSolver::wallFriction() const {
  return friction_->active() ? &wallFriction_ : nullptr;
}

TimeStepLimits IsphSolver::nextDeltaT(const Time& time) const {
  double maxSpeed = 0;
  for (std::size_t a = 0; a < ps_.ownMaterial(); ++a) maxSpeed = std::max(maxSpeed, ps_.cloud.U[a].norm());
  maxSpeed = maxOverRanks(maxSpeed);  // parallel: all ranks
  // The explicit deviatoric term is stable below dt ≤ C_ν ρ h²/η: the largest η/ρ of the
  // last step (the models' bound before the first); the implicit step has no such limit.
  double maxNu = 0;
  if (!viscous_) {
    if (eta_.empty()) {
      for (std::size_t i = 0; i < materials_->size(); ++i) {
        maxNu = std::max(maxNu, (*materials_)[i].maxViscosity() / (*materials_)[i].rho());
      }
    } else {
      maxNu = maxNu_;
    }
  }
  double force = g_.norm() + maxViscousAcceleration_;
  if (wcsph_) {  // the acoustic Courant limit, and the force limit from the whole acceleration
    maxSpeed += waveSpeed_ > 0 ? waveSpeed_ : wcsph_->soundSpeed();  // elasticPlastic: the P wave
    force = std::max(force, maxAcceleration_);
  }
  const double previous = time.timeIndex() > 0 ? time.deltaT() : 0.0;
  return timeStepLimits(kernel_->h(), maxSpeed, time.settings().maxCo, force, schemes_.forceFactor, maxNu,
                        schemes_.viscousFactor, previous, schemes_.maxGrowth, time.settings().maxDeltaT);
}

StepReport IsphSolver::step(const Time& time) {
  ++stepsTaken_;
  if (wcsph_) return stepWeaklyCompressible(time);
  const double dt = time.deltaT();
  StepReport report;
  {
    const bool reorder = stepsSinceReorder_++ % reorderInterval == 0;
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
  // The pressure is the only particle field changed before the PPE has converged (positions
  // and velocities change after it): kept to restore the step start if it does not.
  pStart_ = ps_.cloud.p;
  {
    auto t = timer_.scope("kernel and corrections");
    correction_.update(ps_, schemes_.kernelCorrection, schemes_.correctionMinDeterminant);
    freeSurface_->detect(ps_);
    report.freeSurface = freeSurface_->nSurfaceMaterial();
    prepareWallPressure(freeSurface_->flags());
  }
  intermediateVelocity(time, report);
  if (!report.viscous.empty() && report.failedSolve() != &report.ppe) {
    viscous_->renumbered();  // nothing has moved yet; a retry (stepWithRetry) builds a fresh hierarchy for U
    ps_.cloud.p = pStart_;   // (the lagged pressure's smoothing may have changed it)
    return report;
  }
  {
    if (!lagged_.empty()) {
      // The increment that the step applies to the predictor that saw pⁿ.
      report.ppe = ppe_->solveIncrement(ps_, *kernel_, correction_, ustar_, freeSurface_->flags(), g_, dt, increment_);
    } else {
      report.ppe = ppe_->solve(ps_, *kernel_, correction_, ustar_, freeSurface_->flags(), g_, dt);
    }
    timer_.add("PPE assembly", ppe_->assemblySeconds() + report.ppe.assemblySeconds);
    timer_.add("PPE setup", report.ppe.setupSeconds);
    timer_.add("PPE solve", report.ppe.solveSeconds);
  }
  if (report.failedSolve()) {  // the particles as at the step start; the caller decides (stepWithRetry)
    ps_.cloud.p = pStart_;
    return report;
  }
  {
    auto t = timer_.scope("velocity correction and shifting");
    std::vector<Vec3> oldU(ps_.cloud.U.begin(), ps_.cloud.U.begin() + static_cast<long>(ps_.nMaterial));
    if (!lagged_.empty()) {
      correctVelocityIncrement(ps_, correction_, ustar_, increment_, dt);
      exchangeGhosts(ps_, ps_.cloud.U);  // parallel
      std::vector<Vec3> ustarTotal(ustar_);  // the walls' pressure from the whole condition
      for (std::size_t a = 0; a < ps_.nMaterial; ++a) ustarTotal[a] -= dt * lagged_[a];
      updateWallPressure(ps_, ustarTotal, g_, dt);
    } else {
      correctVelocity(ps_, correction_, ustar_, g_, dt,
                      schemes_.pressureGradient == PressureGradientForm::symmetric ? kernel_.get() : nullptr);
      exchangeGhosts(ps_, ps_.cloud.U);  // parallel
    }
    for (std::size_t a = 0; a < ps_.nMaterial; ++a) {
      ps_.cloud.positions[a] += 0.5 * dt * (oldU[a] + ps_.cloud.U[a]);
    }
    finishStep(time, report);
  }
  return report;
}

StepReport IsphSolver::stepWeaklyCompressible(const Time& time) {
  const double dt = time.deltaT();
  const double h = kernel_->h();
  StepReport report;
  report.ppe.converged = true;  // no PPE: nothing for stepWithRetry to redo
  {
    auto t = timer_.scope("neighbour search");
    if (stepsSinceReorder_++ % reorderInterval == 0) {
      const std::vector<int> order = reorderMaterialParticles(ps_, kernel_->supportRadius());
      wcsph_->permute(order);
      if (elastic_) elastic_->permute(order);
    }
    ps_.neighbours.build(ps_.cloud.positions, *kernel_);
  }
  {
    auto t = timer_.scope("kernel and corrections");  // the strain rate's corrected gradients
    correction_.update(ps_, schemes_.kernelCorrection, schemes_.correctionMinDeterminant);
    if (schemes_.shifting) {  // only the shifting needs the free surface
      freeSurface_->detect(ps_);
      report.freeSurface = freeSurface_->nSurfaceMaterial();
    }
  }
  {
    auto t = timer_.scope("rheology");
    if (elastic_) {  // s^{n+1} from uⁿ, then the momentum with it: symplectic in (s, u)
      elastic_->update(ps_, *materials_, dt);
    } else {
      updateRheology();
      keepActingStress(nullptr);
    }
  }
  {
    auto t = timer_.scope("forces and density");
    {  // (p^n of the material is the one set from ρ^n at the end of the last step, or read)  // the walls' pressures for the force routine and the friction: the material's, extrapolated
      prepareWallPressure(std::vector<char>(ps_.nMaterial, 0));
      const std::vector<Vec3> atRest(ps_.nMaterial, Vec3(dt * g_));
      updateWallPressure(ps_, atRest, g_, dt);
    }
    const std::vector<double> rate = wcsph_->densityRate(ps_, *kernel_, g_, h);
    // g and the explicit deviatoric term (Eq. 6 as written; elasticPlastic: its stress, below),
    // then pressure and artificial viscosity.
    if (elastic_) {
      ustar_.assign(ps_.size(), Vec3::Zero());
      for (std::size_t a = 0; a < ps_.nMaterial; ++a) ustar_[a] = ps_.cloud.U[a] + dt * g_;
      maxViscousAcceleration_ = 0;
    } else {
      maxViscousAcceleration_ = IntermediateVelocity::compute(ps_, *materials_, eta_, g_, dt, h, ustar_);
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
    applyExplicitFriction(dt);
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
  {
    auto t = timer_.scope("shifting and safeguards");
    finishStep(time, report);
  }
  return report;
}

void IsphSolver::finishStep(const Time& time, StepReport& report) {
  const double dt = time.deltaT();
  if (schemes_.shifting) {
    report.maxShift = shiftParticles(ps_, *kernel_, freeSurface_->flags(), schemes_, dt).maxShift;
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
  checkDomain(time);
}

void IsphSolver::checkDomain(const Time& time) const {
  for (std::size_t a = 0; a < ps_.ownMaterial(); ++a) {  // (parallel: the own; an error ends every rank)
    const Vec3& x = ps_.cloud.positions[a];
    const Vec3& u = ps_.cloud.U[a];
    if (!x.allFinite() || !u.allFinite() || !std::isfinite(ps_.cloud.p[a])) {
      fatalError(fmt::format("the solution diverged at time {}: particle {} (origId {}) has a non-finite position, "
                             "velocity or pressure.\n    The last written time directory is intact; try a smaller "
                             "maxCo or maxDeltaT.",
                             time.timeName(), a, ps_.cloud.origId[a]));
    }
    if ((x.array() < domainMin_.array()).any() || (x.array() > domainMax_.array()).any()) {
      fatalError(fmt::format("particle {} (origId {}) left the domain at time {}: position ({:.4g} {:.4g} {:.4g}), "
                             "velocity ({:.3g} {:.3g} {:.3g}); the domain is the initial bounding box enlarged by "
                             "its largest side, ({:.4g} {:.4g}) to ({:.4g} {:.4g}).\n    The last written time directory "
                             "is intact.",
                             a, ps_.cloud.origId[a], time.timeName(), x.x(), x.y(), x.z(), u.x(), u.y(), u.z(),
                             domainMin_.x(), domainMin_.y(), domainMax_.x(), domainMax_.y()));
    }
  }
}

void IsphSolver::write(Time& time) {
  auto t = timer_.scope("output");
  StagedDirectory dir(time.timePath());  // (parallel: processor<rank>/<time>, the own particles)
  FieldWriteOptions options{time.settings().writeFormat, time.settings().writePrecision, ""};
  writeCloud(dir.path(), time.timeName(), distributed_ ? ownedCloud(ps_) : ps_.cloud, options);
  std::vector<label> flags(freeSurface_->flags().begin(), freeSurface_->flags().end());
  flags.resize(ps_.size(), 0);
  options.location = fmt::format("{}/lagrangian/{}", time.timeName(), ps_.cloud.name);
  writeField(dir.path() / "lagrangian" / ps_.cloud.name / "freeSurface", ownedValues(ps_, flags), options);
  if (const auto* tau = deviatoricStress()) {
    writeField(dir.path() / "lagrangian" / ps_.cloud.name / "tau", ownedValues(ps_, *tau), options);
  }
  if (const auto* friction = wallFriction()) {
    writeField(dir.path() / "lagrangian" / ps_.cloud.name / "wallFriction", ownedValues(ps_, *friction), options);
  }
  if (wcsph_) writeField(dir.path() / "lagrangian" / ps_.cloud.name / "rho", wcsph_->density(), options);
  writeStepState(dir.path(), currentState(), options.format);
  time.writeTimeState(dir.path());
  dir.commit();
  time.purgeOldWrites();
  // A restart from this time builds fresh AMG hierarchies (they cannot be written): so does
  // the uninterrupted run, and the two go on bit for bit.
  ppe_->renumbered();
  if (viscous_) viscous_->renumbered();
}

}  // namespace isph
