#pragma once
// How the equations are discretised: system/isphSchemes. Every keyword has a default that
// is echoed in the log; unknown keywords get a "did you mean" warning.
//
//   method           isph;           // | wcsph: the solver class, by name (solvers/): the projection
//                                    // (the paper's method, ProjectionSolver), or the explicit
//                                    // weakly-compressible baseline (WeaklyCompressibleSolver)
//   wcsph            { soundSpeed 20; densityDiffusion 0.1; artificialViscosity 0.1; }
//                    soundSpeed [m/s]: c0 of the equation of state (default 10 sqrt(2 |g| H), H the
//                    height of the scene: 10x the speed of a free fall over it); densityDiffusion:
//                    δ of δ-SPH (0: off); artificialViscosity: Monaghan's α (0: off; with 0.01 the
//                    tank at rest of hydrostaticTank was 2-3 times noisier). With wcsph the
//                    deviatoric term is explicit and controlDict's maxCo is the acoustic Courant
//                    number, dt ≤ maxCo h/(c0 + |u|max); the projection's keywords (laplacian, source)
//                    are not read: a warning names each one given.
//   kernel           WendlandC2;     // | cubicSpline: read by src/sph (makeKernel), as particleMesh
//   hOverDx          1.3;            // and sampleForces read them
//   kernelCorrection on;             // renormalised gradients (strain rate, divergence, shifting)
//   laplacian        { eta 0.1; correction on; }  // Shao & Lo Laplacian (Eq. 10), η = eta·h;
//                    correction: consistent for linear fields where the support is cut
//   source           { type densityInvariant; alpha 0.05; relaxation 0.1; }  // | divergence | mixed
//                    relaxation: share of the compression beyond the lattice density undone per
//                    step where the support reaches the free surface or a wall (see the PPE)
//   freeSurface      { threshold 1.5; gradientThreshold 0.05; minNeighbourFraction 0.5;
//                      compressed granular; }  // | none | all: flagged particles that are
//                    compressed stay unknowns of the PPE (for granular materials by default)
//   tensionCutoff    on;             // p ← max(p, 0) after the solve (no tension)
//   shifting         { enabled on; coefficient 2; maxShift 0.2; nearSurface none; speed velocity; }
//                    // Lind et al. (2012); nearSurface pairs: next to the free surface the
//                    // pair term alone (ParticleShifting.hpp), none: no shift there; speed
//                    // deformation: D = A h (h |γ̇|) dt, so that a body moving as a whole is
//                    // not shifted (every granular scene), velocity: Lind's A h |u| dt (water)
//   timeStep         { forceFactor 0.25; viscousFactor 0.125; maxGrowth 1.1; }
//   wallSafeguard    { distance 0.5; }   // in dx: penetration safeguard
//   collision        { distance 0.5; }   // in dx: material pairs closer than this are
//                                    // separated as inelastic contacts (0: off)
//   viscousTerm      implicit;       // | explicit: the deviatoric term of Eq. 6, a stage read by
//                                    // stages/DeviatoricTerm.hpp (and refused as implicit by wcsph)
//   wallFriction     { slipSpeed 1e-5; passes 10; normalForce wallPressure; }
//                                    // slipSpeed [m/s]: Coulomb walls stick
//                                    // below it (default 1e-4 sqrt(|g| dx)); passes: at most
//                                    // this many velocity solves per step to settle the
//                                    // stick/slip state of each particle on a wall (2-3 on
//                                    // average; see WallFrictionActiveSet.hpp); normalForce: the
//                                    // capacity is tan δ times the walls' pressure (wallPressure),
//                                    // or times the material's pressure carried to the wall
//                                    // hydrostatically (hydrostatic; WallFriction.hpp)
//
// Removed, a fatal error at their line (issue 48: every scene runs the plain projection with
// the renormalised Eq. 11; doc/notes/granularStep.md): incrementalPressure, laggedPressure,
// pressureGradient.
#include <string>

#include "core/dictionary/Dictionary.hpp"

namespace isph {

enum class Method { isph, wcsph };
enum class PpeSource { densityInvariant, divergence, mixed };
enum class CompressedSurface { none, granular, all };
enum class FrictionNormal { wallPressure, hydrostatic };       // the wall stress the Coulomb capacity is tan δ times

// The weakly-compressible method's own settings (WeaklyCompressibleStep), `wcsph { }`.
struct WcsphSettings {
  double soundSpeed = 0;             // m/s; 0: not given (the solver takes it from the scene)
  double densityDiffusion = 0.1;     // δ
  double artificialViscosity = 0.1;  // α
};

// The PPE's settings (PressurePoissonEquation): `laplacian { }` and `source { }`.
struct PpeSettings {
  double laplacianEta = 0.1;  // η/h in r² + η²
  bool laplacianCorrection = true;  // first-order consistent Laplacian where the support is cut
  PpeSource source = PpeSource::densityInvariant;
  double alpha = 0.05;  // weight of the density term in the mixed source
  double boundaryRelaxation = 0.1;  // compression undone per step next to the surface and walls
};

// The particle shifting's settings (ParticleShifting), `shifting { }`.
struct ShiftingSettings {
  bool enabled = true;
  double coefficient = 2.0;  // A in D = A h |u| dt
  double maxShift = 0.2;     // in dx
  bool pairsNearSurface = false;  // shifting { nearSurface pairs; }
  bool deformationSpeed = false;  // shifting { speed deformation; }: D from h |γ̇|, else from |u| (Lind)
};

struct IsphSchemes {
  Method method = Method::isph;
  WcsphSettings wcsph;

  bool kernelCorrection = true;
  double correctionMinDeterminant = 0.25;  // fall back to the raw gradient below this

  PpeSettings ppe;

  double freeSurfaceThreshold = 1.5;         // ∇·r below this flags the free surface
  double freeSurfaceGradient = 0.05;         // |∇C| h above this makes a candidate for the scan
  double minNeighbourFraction = 0.5;         // fewer neighbours than this share of a full lattice: surface
  CompressedSurface compressedSurface = CompressedSurface::granular;

  bool tensionCutoff = true;  // p ← max(p, 0) (after the PPE solve; the WCSPH equation of state)

  ShiftingSettings shifting;

  double forceFactor = 0.25;     // dt ≤ C_f √(h/|f|)
  double viscousFactor = 0.125;  // dt ≤ C_ν ρ h²/η
  double maxGrowth = 1.1;        // dt may grow by at most this factor per step

  double wallSafeguardDistance = 0.5;  // in dx
  double collisionDistance = 0.5;      // in dx; 0: off

  double frictionSlipSpeed = -1;  // m/s; < 0: not given (the solver takes 1e-4 sqrt(|g| dx))
  int frictionPasses = 10;
  FrictionNormal frictionNormal = FrictionNormal::wallPressure;

  // The shared settings; the stages' entries (viscousTerm) are read by the stages, and the
  // solver checks for unknown keywords once they have been (Dictionary::checkKeywords).
  static IsphSchemes read(const Dictionary& dict, int dimension);
  // One line per setting for the start of the log.
  std::string describe() const;
};

const char* toString(PpeSource s);

}  // namespace isph
