#pragma once
// A function object, as OpenFOAM's: work done inside the solver's time loop (here: the
// forces on wall patches every N steps), declared by name in system/controlDict
//
//   functions
//   {
//       barrierForce                 // the name: postProcessing/barrierForce/<startTime>/
//       {
//           type          patchForces;   // chosen by name from a registry
//           writeInterval 1;             // optional: every N time steps (default 1)
//           ...                          // the type's own entries
//       }
//   }
//
// A new type registers a factory under its name (FunctionObjectRegistry) in its own file;
// the solver never changes.
#include <string>
#include <vector>

#include "core/Registry.hpp"
#include "core/Types.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/time/Time.hpp"
#include "particles/ParticleCloud.hpp"
#include "sph/kernels/Kernel.hpp"
#include "sph/neighbours/NeighbourList.hpp"

namespace isph {

// What the solver hands its function objects at the end of a step: the cloud as it would be
// written now (positions, velocities, the pressures of material, wall and dummy particles)
// and, for materials with a deviatoric stress, that stress with the kernel and neighbour list.
struct SolverState {
  const ParticleCloud& cloud;
  const std::vector<SymmTensor>* tau = nullptr;  // per particle; null: none
  const Kernel* kernel = nullptr;
  const NeighbourList* neighbours = nullptr;     // over cloud.positions, if the solver has one
  const std::vector<Vec3>* wallFriction = nullptr;  // the Coulomb friction traction on the walls; null: none
  const Vec3* gravity = nullptr;                    // the solver's g [m/s²] (momentumBalance); null: none
  // A parallel run: which particles of `cloud` are this rank's own (1) rather than ghosts (0);
  // a function object sums over the own ones, reduces over the ranks and writes on rank 0.
  // Null: a serial run.
  const std::vector<char>* owned = nullptr;
};

class FunctionObject {
 public:
  // Reads `writeInterval` (a whole number of steps >= 1; FatalError naming the entry otherwise).
  FunctionObject(std::string name, const Dictionary& dict);
  virtual ~FunctionObject() = default;

  const std::string& name() const { return name_; }
  label writeInterval() const { return writeInterval_; }
  // True on the steps whose time index is a multiple of writeInterval.
  bool due(const Time& time) const { return time.timeIndex() % writeInterval_ == 0; }

  virtual std::string type() const = 0;
  // Do the work for this step (called only when due()).
  virtual void execute(const Time& time, const SolverState& state) = 0;
  // One line for the log at start: what it does and where it writes.
  virtual std::string describe() const = 0;
  // At the end of the run (endTime or a stop by signal), after the last step: what is written
  // from the whole history (patchForces: its filtered trace). Default: nothing.
  virtual void end(const Time& /*time*/) {}

 private:
  std::string name_;
  label writeInterval_ = 1;
};

using FunctionObjectRegistry = Registry<FunctionObject, const std::string&, const Dictionary&, const Time&>;

}  // namespace isph
