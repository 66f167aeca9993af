#pragma once
// processor<i>/decomposition: what a decomposition was when it was written, so that a reader of
// the processor directories can tell a whole decomposition from what is left of one (a
// processor folder removed or not copied back from a cluster):
//
//   numberOfSubdomains  2;     // the processor folders written
//   particles           617;   // the particles of the case (the same at every time: the solver
//                              //   creates and deletes none)
//
// decomposePar writes it into every processor folder, and so does a parallel run that decomposed
// its start time in memory (each rank into its own). reconstructPar and the utilities given
// -parallel check the folders against it (wholeDecomposition); a case decomposed before the
// record existed is checked against system/decomposeParDict's numberOfSubdomains.
#include <filesystem>
#include <optional>
#include <string>

namespace isph {

struct DecompositionRecord {
  int numberOfSubdomains = 0;
  long particles = 0;  // 0: not recorded
  std::string source;  // the file it was read from (for messages)
};

// Writes <processorDir>/decomposition (atomically).
void writeDecompositionRecord(const std::filesystem::path& processorDir, int numberOfSubdomains, long particles);

// The processor directories of a case, checked whole: their number is the recorded
// numberOfSubdomains (processor<i>/decomposition of the first folder that has one, else
// system/decomposeParDict's). FatalError naming the missing folders otherwise, or when there
// are none; with `force` a warning, and the record's particle count is not held against the times
// (particles 0).
DecompositionRecord wholeDecomposition(const std::filesystem::path& caseDir, bool force = false);

// FatalError (or, with `force`, nothing) when a time of the processor directories holds another
// number of particles than the record says: a processor lost particles, or the time is damaged.
void checkWholeTime(const DecompositionRecord& record, const std::string& timeName, std::size_t particles);

}  // namespace isph
