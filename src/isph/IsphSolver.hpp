#pragma once
// One ISPH projection step (Chorin; the paper's Eqs. 6-11), as a short list of named
// stages over small single-purpose classes:
//   neighbours → kernel correction → free surface → u* (Eq. 6) → PPE (Eqs. 8/10) →
//   velocity correction (Eq. 11) → move → shift → wall safeguard
// or, with isphSchemes `method wcsph;`, the explicit weakly-compressible step over the same
// pieces (WeaklyCompressibleStep.hpp). The solver owns the particles; the application's main
// owns the time loop.
//
// Incremental projection (isphSchemes `incrementalPressure granular|all;`, default none; only
// with the semi-implicit viscous term): the viscous solve of u* sees the pressure force of the
// last step (laggedPressureForce), the PPE solves for the increment δp = p^{n+1} − pⁿ and
// Eq. 11 corrects with ∇δp (Goda 1979; van Kan 1986). The plain projection moves each
// particle by its own −dt²∇p/ρ after the viscous solve, which the deviatoric stress never
// resists: next to the free faces of a stiff block, where ∇p is not a rigid-body field, that
// spread a block that should stick along its bed at 1.5 cm/s. With it the stress resists the
// pressure as the coupled equations would, and δp → 0 in material at rest. By default the
// lagged pressure force is the conservative pair form, so the pressure inside a zone moving
// as a rigid body exerts no net force on it, and the walls' pairs are exactly the normal
// reaction that Coulomb friction is limited by (WallFriction); `laggedPressure { form
// gradient; smoothing 3; }` uses the gradient of Eq. 11 instead, consistent where the support
// is cut (LaggedPressure.hpp: with it a collapsing column keeps its static wedge; with the
// pair form's error at the free surface the column ran off its floor). The first step of a
// fresh start is a plain one.
// Not the default: in such zones the pressure is carried from step to step and its
// distribution is statically undetermined, so it follows the history: a layer at rest on a
// slope between end walls (granularAtRest) stays put (0.85 mm) but ends with p 20 % (L2) off
// the infinite-slope lithostatic field, its end walls taking load as buttresses (16 % with
// the gradient form, a uniform excess of 7 % of ρ g H; the barrier's deposit then presses on
// the barrier with more than its along-bed weight: doc/notes/columnCollapse.md).
#include <filesystem>
#include <memory>
#include <optional>

#include "core/PhaseTimer.hpp"
#include "core/time/Time.hpp"
#include "isph/ElasticPlasticStress.hpp"
#include "isph/FreeSurfaceDetector.hpp"
#include "isph/ImplicitViscousStep.hpp"
#include "isph/StepState.hpp"
#include "isph/IsphSchemes.hpp"
#include "isph/KernelGradientCorrection.hpp"
#include "isph/ParticleSystem.hpp"
#include "isph/PressurePoissonEquation.hpp"
#include "isph/StrainRate.hpp"
#include "isph/WallFriction.hpp"
#include "isph/TimeStepControl.hpp"
#include "isph/WeaklyCompressibleStep.hpp"
#include "isph/parallel/DistributedParticles.hpp"

namespace isph {

struct StepReport {
  std::vector<SolverPerformance> viscous;  // the implicit deviatoric term, one per component
  SolverPerformance ppe;
  std::size_t freeSurface = 0;
  std::size_t collisions = 0;  // material particles separated from a too-close neighbour
  std::size_t wallSafeguard = 0;
  std::size_t wallCrossings = 0;  // this step
  double maxShift = 0;  // in dx
  double densityVariation = -1;  // wcsph: the largest |ρ/ρ0 − 1| of the material (−1: isph)
  double maxSpeed = 0;
  double courant = 0;

  // The first solve of the step that did not converge (the viscous ones, then the PPE), or
  // null: the particles are then as at the step start (stepWithRetry redoes the step).
  const SolverPerformance* failedSolve() const {
    for (const auto& v : viscous) {
      if (!v.converged) return &v;
    }
    return ppe.converged ? nullptr : &ppe;
  }
};

class IsphSolver {
 public:
  // Reads the cloud of the start time, constant/materialProperties, constant/g,
  // system/isphSchemes and system/isphSolution; logs the active models and schemes.
  // `parallel`: a run on the MPI ranks of mpirun -np N (doc/parallel.md): this rank's part
  // of the particles, from processor<rank>/ or decomposed in memory; every loop over the
  // particles runs over this rank's own and ghost particles, the linear systems over all
  // ranks, every global figure is a reduction, and write() writes processor<rank>/<time>.
  explicit IsphSolver(const Time& time, bool parallel = false);
  ~IsphSolver();

  // The time step for the next step (adjustTimeStep), with the limit that set it.
  TimeStepLimits nextDeltaT(const Time& time) const;
  // Advance the particles by time.deltaT() (call after ++time). When the implicit viscous
  // step or the PPE does not converge (report.failedSolve()) the particles are left as at the
  // step start, so that the step can be redone with a smaller deltaT (stepWithRetry).
  StepReport step(const Time& time);
  // Write the cloud into the current time directory (atomically) and the time state.
  void write(Time& time);

  const ParticleSystem& particles() const { return ps_; }
  const PhaseTimer& timer() const { return timer_; }
  const Kernel& kernel() const { return *kernel_; }
  // The deviatoric stress τ that acted in the last step (zero for walls; keepActingStress),
  // or null when no material has one; before the first step, 2 η D of the state read.
  const std::vector<SymmTensor>* deviatoricStress();
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
  // "AMG hierarchies built for p: N of M solves" (and for U), for the end of the log.
  std::string preconditionerSummary() const;
  const Vec3& gravity() const { return g_; }
  // A parallel run's decomposition (null in a serial run).
  const DistributedParticles* distributed() const { return distributed_.get(); }

 private:
  void checkDomain(const Time& time) const;
  // `heights`: the scene scales of a restart's state (else from the material's extent).
  void setSceneScales(const std::vector<double>* heights);
  // What the steps carry from one to the next, written with each time (StepState.hpp).
  StepState currentState() const;
  void restoreState(const StepState& state);
  // The wall pull limits and tangential pressure gradients that WallBoundaryPressure uses.
  void prepareWallPressure(const std::vector<char>& freeSurface);
  void initialiseWallPressure();
  // The explicit Coulomb friction on u* and the walls' share of it (wallFriction_).
  void applyExplicitFriction(double dt);
  // Strain rate and η of the material particles at the current state (empty η if inviscid).
  void updateRheology();
  // τ = 2 ηⁿ D(u) of the step into tau_: u = u* (semi-implicit term) or, null, uⁿ (explicit).
  void keepActingStress(const std::vector<Vec3>* ustar);
  void intermediateVelocity(const Time& time, StepReport& report);
  // The weakly-compressible step (method wcsph) in place of the projection.
  StepReport stepWeaklyCompressible(const Time& time);
  // After the particles moved: shifting, minimum distance, wall safeguard, speed, domain.
  void finishStep(const Time& time, StepReport& report);

  std::size_t totalWallCrossings_ = 0;
  std::size_t totalSafeguard_ = 0, totalCollisions_ = 0;  // particle-steps (all ranks)
  double materialParticleSteps_ = 0;                       // Σ over the steps of the material particles
  std::size_t nMaterialAll_ = 0;                           // material particles on all ranks
  IsphSchemes schemes_;
  std::unique_ptr<MaterialTable> materials_;
  std::unique_ptr<Kernel> kernel_;
  ParticleSystem ps_;
  Vec3 g_ = Vec3::Zero();
  KernelGradientCorrection correction_;
  std::unique_ptr<FreeSurfaceDetector> freeSurface_;
  std::unique_ptr<PressurePoissonEquation> ppe_;
  std::vector<Vec3> ustar_;
  std::vector<Vec3> lagged_;        // −∇pⁿ/ρ of the incremental projection (empty: off)
  std::vector<double> increment_;   // p^{n+1} − pⁿ of the material (incremental projection)
  bool incremental_ = false;        // incremental projection active
  bool freshStart_ = false;         // started from particleMesh's fields (no wall pressures)
  // The incremental projection in this step: not in the first step of a fresh start, which
  // finds the pressure that it carries.
  bool incrementalNow() const { return incremental_ && viscous_ && !(freshStart_ && stepsTaken_ <= 1); }
  StrainRate strain_;
  std::vector<double> eta_;  // effective viscosity of the material particles (time n)
  double maxNu_ = 0;          // the largest η/ρ of the last step (explicit viscous limit)
  std::unique_ptr<WallFriction> friction_;
  std::vector<Vec3> wallFriction_;  // per particle: the walls' friction traction [Pa]
  std::unique_ptr<ImplicitViscousStep> viscous_;
  std::unique_ptr<WeaklyCompressibleStep> wcsph_;  // method wcsph (null: the projection)
  std::unique_ptr<ElasticPlasticStress> elastic_;  // wcsph with elasticPlastic materials (null: viscous)
  double waveSpeed_ = 0;  // elasticPlastic: the P-wave speed, the acoustic Courant limit's
  double maxAcceleration_ = 0;  // wcsph: the largest |du/dt| of the last step (force limit)
  std::vector<scalar> pStart_;  // p at the step start (restored when the PPE fails)
  Vec3 domainMin_, domainMax_;
  std::vector<double> sceneHeights_;  // each material's height, the scale of its default etaMax
  double maxViscousAcceleration_ = 0;
  long stepsSinceReorder_ = 0;
  long stepsTaken_ = 0;
  long tauStep_ = -1;
  std::vector<SymmTensor> tau_;
  PhaseTimer timer_;
  std::unique_ptr<DistributedParticles> distributed_;  // parallel: doc/parallel.md (null: serial)
};

}  // namespace isph
