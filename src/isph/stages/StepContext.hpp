#pragma once
// What the projection step's stages (DeviatoricTerm, Projection) are built from and work on.
// The solver (solvers/ProjectionSolver) owns every object named here; a stage holds only its
// own state (a linear solver, the lagged pressure), so that one variant of the step is one
// class with one job and a new variant never edits the solver.
#include <vector>

#include "core/PhaseTimer.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "isph/discretisation/FreeSurfaceDetector.hpp"
#include "isph/IsphSchemes.hpp"
#include "isph/discretisation/KernelGradientCorrection.hpp"
#include "isph/ParticleSystem.hpp"
#include "isph/deviatoric/ViscousStress.hpp"
#include "isph/walls/WallBoundary.hpp"
#include "isph/walls/WallFriction.hpp"
#include "isph/materials/MaterialTable.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph {

// For building a stage: each reads its own entries of system/isphSchemes (and its linear
// solver's of system/isphSolution) and refuses, at the entry's line, a setting that it would
// ignore.
struct StageSetup {
  const Dictionary& schemes;   // system/isphSchemes
  const Dictionary& solution;  // system/isphSolution
  const IsphSchemes& common;   // the settings every stage shares (wallFriction's passes, ...)
  const MaterialTable& materials;
  int dimension;
};

// For a step: the particles and the models the stages read and update.
struct StepContext {
  ParticleSystem& ps;
  const MaterialTable& materials;
  const Kernel& kernel;
  const KernelGradientCorrection& correction;
  const FreeSurfaceDetector& freeSurface;
  WallBoundary& walls;
  WallFriction& friction;
  ViscousStress& viscousStress;
  PhaseTimer& timer;
  const Vec3& g;
  std::vector<Vec3>& wallFriction;  // the walls' friction traction of the step [Pa] (WallFriction::wallTraction)
};

}  // namespace isph
