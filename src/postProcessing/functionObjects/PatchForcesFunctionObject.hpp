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
//       filterWindow  0.01;        // optional [s]: the filtered trace's centred moving average
//       lateForceWindow 0.25;      // optional [s]: the late force's span at the end of the run
//   }
//
// Output: postProcessing/<name>/<startTime>/force.dat, the columns and header of
// sampleForces' <set>.dat (ForceTable: a `# Time [s] Fx [N/m] ...` line names every column
// and unit, and the header says whether forces are per metre or over the width). A restart
// starts a new file under its own start time, as OpenFOAM does (a run from the same start
// time again replaces its file).
//
// Beside it, forceFiltered.dat (the same columns filtered by a centred moving average over
// filterWindow) and forceFigures.txt (the filtered peak of Fn and its time, the late force,
// the raw maximum; FilteredForces.hpp), written at every write time and at the end of the run.
// They cover the whole run: a continued run takes the rows of the earlier start times'
// force.dat (each up to the next start) before its own, as keyFigures joins them.
//
// The file is a history appended row by row, not replaced: a temporary name and rename
// (AtomicFile.hpp) would copy the whole file every step. Each row is written with one
// write and flushed, so a crash leaves every row written before it complete and readable.
#include <filesystem>
#include <optional>

#include "postProcessing/forces/FilteredForces.hpp"
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
  void end(const Time& time) override;

  const std::filesystem::path& file() const { return file_; }

 private:
  std::vector<ForceSet> set_;  // one set (setForces takes a list)
  std::filesystem::path file_;
  std::optional<ForceTable> table_;  // from the first execute (the dimension is the cloud's)
  RowFile out_;
  std::string header_;               // the raw table's comment lines
  std::vector<std::vector<double>> rows_;  // the whole run's rows (earlier start times' first; rank 0)

  ForceFigures writeFiltered() const;
};

}  // namespace isph
