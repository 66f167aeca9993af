#pragma once
// What an ISPH run carries from one step to the next besides the particle fields and the time
// state (uniform/time): written with every time directory and read back at a restart, so that
// a run restarted from a written time continues bit for bit as the uninterrupted one
// (tests/isph/RestartTest.cpp).
//
//   <time>/uniform/isphState          the counters and scalars below (a dictionary)
//   <time>/uniform/frictionStates     stick/slip state at the walls, by origId (labelField)
//   <time>/uniform/slipDirections     the slip direction of each sliding particle, by origId
//   <time>/uniform/viscousIncrements  the velocity solve's warm start (U { warmStart lastIncrement;
//   })
//
// Carried: the step count and the reordering counter (the material is reordered by cell every
// 50 steps: the storage order), the limits of the next step (the largest η/ρ, viscous and
// total accelerations), the scene scales that set the default etaMax and the WCSPH sound speed
// (from the material's height at the first start, not at the restart), the domain that the
// particles must stay in, and the active set's stick/slip states (a restart that took them
// afresh from the velocities needed 4 velocity solves in its first step against 1). The AMG
// hierarchies of the linear solvers cannot be written: the solver rebuilds them after every
// write, in the uninterrupted run as in the restart. Exact: doubles are written in their
// shortest round-trip form (the arrays in binary, or ascii with 17 digits).
#include <filesystem>
#include <optional>
#include <vector>

#include "core/Types.hpp"
#include "core/fields/FieldIO.hpp"

namespace isph {

struct StepState {
  long stepsTaken = 0;
  long stepsSinceReorder = 0;
  bool freshStart = false;
  bool viscosityKnown = false;  // η of a step exists (the explicit viscous limit uses maxNu)
  double maxNu = 0;
  double maxViscousAcceleration = 0;
  double maxAcceleration = 0;
  double soundSpeed = 0;  // WCSPH (0: not a WCSPH run)
  Vec3 domainMin = Vec3::Zero(), domainMax = Vec3::Zero();
  std::vector<double> materialHeights;  // the scene scale of each material
  // By origId (empty when not used).
  std::vector<label> frictionStates;
  std::vector<Vec3> slipDirections;
  std::vector<Vec3> viscousIncrements;
  double viscousIncrementDt = 0;
};

// Writes the state into <timeDir>/uniform (atomically, each file); `format` as the case's
// fields (ascii with 17 digits, so that it reads back exactly).
void writeStepState(const std::filesystem::path& timeDir, const StepState& state,
                      WriteFormat format);

// The state of <timeDir>, or nullopt when it has none (a time from particleMesh, or written
// before the state was). FatalError naming the file for a damaged one.
std::optional<StepState> readStepState(const std::filesystem::path& timeDir);

}  // namespace isph
