#pragma once
// The processor directories of a decomposed case, as OpenFOAM's:
//   <case>/processor<i>/<time>/lagrangian/<cloud>/<field>   rank i's particles, every field
//   <case>/processor<i>/<time>/uniform/time                 the time state (restarts)
//   <case>/processor<i>/<time>/uniform/isphState, ...        the solver state (StepState.hpp)
// What decomposePar writes and reconstructPar merges back, what a parallel solver run reads
// and writes, and what a post-processing utility given -parallel reads (DecomposedTime).
// Every field file of a cloud travels, whatever its name (the solver's tau, wallFriction,
// freeSurface, rho as well as the cloud's own), in the format it was written in.
#include <filesystem>
#include <string>
#include <vector>

#include "core/time/TimeName.hpp"

namespace isph {

std::string processorName(int i);  // "processor<i>"
// The processor directories processor0 .. processor<n-1> of a case (0: not decomposed).
// FatalError when the numbers have a gap.
int nProcessorDirectories(const std::filesystem::path& caseDir);
// The clouds of a time directory (the folders of <time>/lagrangian), sorted.
std::vector<std::string> cloudNames(const std::filesystem::path& timeDir);

// Writes the particles of every cloud of <case>/<timeName> into <case>/processor<p>/<timeName>
// for p = part[i] (part: one entry per particle of the cloud `cloudName`, in file order;
// other clouds are not supported), each processor's time atomically, with uniform/.
void decomposeTime(const std::filesystem::path& caseDir, const std::string& timeName, const std::string& cloudName,
                   const std::vector<int>& part, int nParts);

// Merges <case>/processor<i>/<timeName> (i < nProcs) into the time folder `target` (normally
// the staging path of a StagedDirectory): every cloud and field, the particles ordered
// material, wall, dummy and each kind by origId; uniform/ from processor0, but its field files
// (the solver's arrays by origId: each rank writes its own particles' entries, StepState.hpp)
// merged, each entry from the processor that holds that particle. FatalError naming
// the processor when one lacks the time, a cloud or a field, or the origIds repeat.
// Returns the number of particles.
std::size_t reconstructTime(const std::filesystem::path& caseDir, int nProcs, const std::string& timeName,
                            const std::filesystem::path& target);

// The times of a decomposed case (processor0's).
std::vector<Instant> decomposedTimes(const std::filesystem::path& caseDir);

// A time as a post-processing utility reads it: <case>/<time>, or, for a decomposed case
// (-parallel), processor*/<time> of the whole decomposition (FatalError otherwise,
// DecompositionRecord.hpp) merged into a hidden folder of the case that is removed
// afterwards, also when the merge fails (a staging name: listTimes skips it, and the recovery
// at the start of the next application clears it if this one was killed; StagingRecovery.hpp).
class DecomposedTime {
 public:
  DecomposedTime(const std::filesystem::path& caseDir, const std::string& timeName, bool decomposed);
  ~DecomposedTime();
  DecomposedTime(const DecomposedTime&) = delete;
  DecomposedTime& operator=(const DecomposedTime&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  bool temporary_ = false;
};

}  // namespace isph
