#pragma once
// Function object `patchForces`: the force of the material on a set of wall patches, every
// writeInterval steps, by the routine sampleForces uses (setForces) on the same particles, so
// that its rows equal sampleForces' at the written times. The entries are a sampleForcesDict
// set's (ForceSet.hpp, read by the same code) plus the function object's own:
//
//   barrierForce
//   {
//       type          patchForces;
//       patches       (barrier);
//       CofR          (0 0 0);     // optional
//       width         0.3;         // optional (2D): forces over this width [N], else per metre [N/m]
//       writeInterval 1;           // optional: every N time steps (default 1)
//   }
//
// Output: postProcessing/<name>/<startTime>/force.dat, the columns and header of
// sampleForces' <set>.dat (ForceTable: a `# Time [s] Fx [N/m] ...` line names every column
// and unit, and the header says whether forces are per metre or over the width). A restart
// starts a new file under its own start time, as OpenFOAM does (a run from the same start
// time again replaces its file).
//
// The file is a history appended row by row, not replaced: a temporary name and rename
// (AtomicFile.hpp) would copy the whole file every step. Each row is written with one
// write and flushed, so a crash leaves every row written before it complete and readable.
#include <filesystem>
#include <optional>

#include "postProcessing/forces/ForceSet.hpp"
#include "postProcessing/forces/ForceTable.hpp"
#include "postProcessing/functionObjects/FunctionObject.hpp"
#include "postProcessing/functionObjects/RowFile.hpp"

namespace isph {

class PatchForcesFunctionObject final : public FunctionObject {
 public:
  PatchForcesFunctionObject(const std::string& name, const Dictionary& dict, const Time& time);

  std::string type() const override { return "patchForces"; }
  void execute(const Time& time, const SolverState& state) override;
  std::string describe() const override;

  const std::filesystem::path& file() const { return file_; }

 private:
  std::vector<ForceSet> set_;  // one set (setForces takes a list)
  std::filesystem::path file_;
  std::optional<ForceTable> table_;  // from the first execute (the dimension is the cloud's)
  RowFile out_;
};

}  // namespace isph
