#pragma once
// What every method of isphLandslideFoam shares: the case it reads (the cloud of the start
// time, constant/materialProperties, constant/g, system/isphSchemes and, for a restart, the
// solver state), the particles, the wall friction, the time-step limits, the end of a step
// (shifting, the safeguards, the domain check) and the writing of a time directory. One class
// per method derives from it and takes the step; isphSchemes' `method` selects it by name:
//   isph   ProjectionSolver (the paper's projection, Eqs. 6-11)
//   wcsph  WeaklyCompressibleSolver (the explicit weakly-compressible baseline)
// The solver owns the particles; the application's main owns the time loop.
//
// `parallel`: a run on the MPI ranks of mpirun -np N (doc/parallel.md): this rank's part of the
// particles, from processor<rank>/ or decomposed in memory; every loop over the particles runs
// over this rank's own and ghost particles, the linear systems over all ranks, every global
// figure is a reduction, and write() writes processor<rank>/<time>.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/PhaseTimer.hpp"
#include "core/Registry.hpp"
#include "core/fields/FieldIO.hpp"
#include "core/time/Time.hpp"
#include "isph/discretisation/FreeSurfaceDetector.hpp"
#include "isph/IsphSchemes.hpp"
#include "isph/discretisation/KernelGradientCorrection.hpp"
#include "isph/ParticleSystem.hpp"
#include "isph/timeStepping/StepReport.hpp"
#include "isph/startup/StartupChecks.hpp"
#include "isph/timeStepping/StepState.hpp"
#include "isph/timeStepping/TimeStepControl.hpp"
#include "isph/deviatoric/ViscousStress.hpp"
#include "isph/walls/WallBoundary.hpp"
#include "isph/walls/WallFriction.hpp"
#include "isph/parallel/DistributedParticles.hpp"

namespace isph {

class ParticleSolver {
 public:
  // The method that system/isphSchemes names (`method isph;` by default), reading the case.
  static std::unique_ptr<ParticleSolver> New(const Time& time, bool parallel = false);
  virtual ~ParticleSolver();

  // The time step for the next step (adjustTimeStep), with the limit that set it.
  TimeStepLimits nextDeltaT(const Time& time) const;
  // Advance the particles by time.deltaT() (call after ++time). When a linear solve does not
  // converge (report.failedSolve()) the particles are left as at the step start, so that the
  // step can be redone with a smaller deltaT (stepWithRetry).
  virtual StepReport step(const Time& time) = 0;
  // Write the cloud into the current time directory (atomically) and the time state.
  void write(Time& time);

  const ParticleSystem& particles() const { return ps_; }
  const PhaseTimer& timer() const { return timer_; }
  PhaseTimer& timer() { return timer_; }  // the time loop's own phases (time step, log, function objects)
  const Kernel& kernel() const { return *kernel_; }
  // The deviatoric stress τ that acted in the last step (zero for walls), or null when no
  // material has one; before the first step, that of the state read.
  virtual const std::vector<SymmTensor>* deviatoricStress();
  // The traction of the material on each wall particle through the Coulomb wall friction of
  // the last step (WallFriction::wallTraction) [Pa], zero off the friction walls; null when no
  // wall has friction for the scene's materials. Written as the field `wallFriction`.
  const std::vector<Vec3>* wallFriction() const;
  // Material particles found behind a wall surface since the start of the run.
  std::size_t wallCrossings() const { return totalWallCrossings_; }
  // The safeguards' work in this run, for the end-of-run summary: the particles the wall
  // penetration guard put back and those the collision separation moved, summed over the
  // steps, and per 10,000 material particle-steps.
  std::string safeguardSummary() const;
  // The linear solvers' work for the end of the log ("AMG hierarchies built for p: N of M").
  virtual std::string preconditionerSummary() const { return {}; }
  const Vec3& gravity() const { return g_; }
  // A parallel run's decomposition (null in a serial run).
  const DistributedParticles* distributed() const { return distributed_.get(); }

 protected:
  ParticleSolver(const Time& time, bool parallel);

  // The method's scales for the time step: a signal speed added to the flow's (the acoustic
  // Courant limit) and an acceleration bound for the force limit beyond g and the viscous term.
  struct MethodScales {
    double signalSpeed = 0;
    double acceleration = 0;
  };
  virtual MethodScales methodScales() const { return {}; }
  // Whether the deviatoric term is explicit (then its viscous time-step limit applies).
  virtual bool explicitDeviatoricTerm() const { return true; }
  // The method's fields beside the cloud's, and its entries of the solver state.
  virtual void writeMethodFields(const std::filesystem::path& cloudDir, const FieldWriteOptions& options) const;
  virtual void saveMethodState(StepState&) const {}
  virtual void restoreMethodState(const StepState&) {}
  // After writing: a restart from this time builds fresh AMG hierarchies (they cannot be
  // written): so must the uninterrupted run, for the two to go on bit for bit.
  virtual void afterWrite() {}
  // The wall patches' boundary condition for the log ("Neumann wall pressure").
  virtual std::string wallCondition() const = 0;
  // The log lines of the method's stages, after the shared schemes' (empty: none).
  virtual std::string describeStages() const { return {}; }

  // The end of the derived constructor: the solver state of a restart, then the log of the
  // active models and schemes, and the warnings for entries of system/isphSchemes no one read.
  void finishConstruction();
  // A field of the start time's cloud in the particles' order, or empty if it was not written
  // (the cloud is reordered after reading). Before finishConstruction only.
  template <class T>
  std::vector<T> readStartField(const std::string& name) const {
    const auto file = startCloudDir_ / name;
    if (!std::filesystem::is_regular_file(file)) return {};
    return inWrittenOrder(readField<T>(file, writtenIds_.size()));
  }

  // Whether this step reorders the material particles along cells (every reorderInterval-th).
  bool reorderDue() { return stepsSinceReorder_++ % reorderInterval == 0; }
  // After the particles moved: shifting, minimum distance, wall safeguard, speed, domain.
  void finishStep(const Time& time, StepReport& report);

  static constexpr long reorderInterval = 50;  // steps between cell reorderings of the material

  std::optional<StepState> state_;  // a restart's solver state (StepState.hpp), else none;
                                    // released by finishConstruction
  Dictionary schemesDict_{"system/isphSchemes"};  // the stages read their entries from it
  IsphSchemes schemes_;
  std::unique_ptr<MaterialTable> materials_;
  std::unique_ptr<Kernel> kernel_;
  ParticleSystem ps_;
  Vec3 g_ = Vec3::Zero();
  KernelGradientCorrection correction_;
  std::unique_ptr<FreeSurfaceDetector> freeSurface_;
  std::unique_ptr<WallFriction> friction_;
  std::unique_ptr<WallBoundary> walls_;  // the walls' pressures and what they are computed from
  std::vector<Vec3> wallFriction_;  // per particle: the walls' friction traction [Pa]
  std::unique_ptr<ViscousStress> viscousStress_;
  std::vector<Vec3> ustar_;  // the step's intermediate velocity u* (Eq. 6)
  bool freshStart_ = false;  // started from particleMesh's fields (no wall pressures)
  double maxViscousAcceleration_ = 0;
  long stepsTaken_ = 0;
  PhaseTimer timer_;
  std::unique_ptr<DistributedParticles> distributed_;  // parallel: doc/parallel.md (null: serial)

 private:
  void setSceneScales(const std::vector<double>* heights);
  void initialiseWallPressure();
  StepState currentState() const;

  template <class T>
  std::vector<T> inWrittenOrder(const std::vector<T>& written) const;

  std::filesystem::path startCloudDir_;
  std::vector<label> writtenIds_;  // the start time's particle ids in the order written
  std::size_t totalWallCrossings_ = 0;
  std::size_t totalSafeguard_ = 0, totalCollisions_ = 0;  // particle-steps (all ranks)
  double materialParticleSteps_ = 0;                       // Σ over the steps of the material particles
  std::size_t nMaterialAll_ = 0;                           // material particles on all ranks
  SceneDomain domain_;  // the particles must stay in it (StartupChecks.hpp)
  std::vector<double> sceneHeights_;  // each material's height, the scale of its default etaMax
  long stepsSinceReorder_ = 0;
};

template <class T>
std::vector<T> ParticleSolver::inWrittenOrder(const std::vector<T>& written) const {
  std::unordered_map<label, std::size_t> at;
  for (std::size_t i = 0; i < writtenIds_.size(); ++i) at[writtenIds_[i]] = i;
  std::vector<T> out(ps_.cloud.origId.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = written[at.at(ps_.cloud.origId[i])];
  return out;
}

// The methods by name (`method` in system/isphSchemes).
using SolverRegistry = Registry<ParticleSolver, const Time&, bool>;

}  // namespace isph
