#pragma once
// Restores or clears what an interrupted write, replace or purge left in a case (AtomicFile.hpp
// says what each point of interruption leaves): every application calls it at start and logs
// what it did.
//
//   .<T>.old.*    with <T> missing: renamed back to <T> (a replace killed between its two
//                 renames; the old directory is complete); with <T> present: removed
//   .<T>.tmp.*    removed (an unfinished write; what it held was never published)
//   .<T>.trash.*  removed (a removal or purge that was killed; <T> was already out of view)
//
// Only leftovers of processes that are gone are touched: a process of this host that is still
// running may be writing them (toVTK started while the solver runs); one of another host (a
// cluster's shared file system) cannot be asked, and is left alone unless the caller writes
// time directories itself (`ownsForeignHosts`: the solver and particleMesh, of which one runs
// on a case at a time).
#include <filesystem>
#include <string>
#include <vector>

namespace isph {

struct StagingRecovery {
  int restored = 0;              // directories renamed back
  int removed = 0;               // leftovers deleted
  int leftAlone = 0;             // of a writer that may still be running
  std::vector<std::string> log;  // one line per entry, for the application's log
};

struct StagingRecoveryOptions {
  bool ownsForeignHosts = false;  // also clear leftovers of other hosts
  bool recursive = true;          // also the sub-directories (postProcessing/, VTK/, times)
};

// Recover `dir` (a missing one gives nothing). FatalError when a leftover cannot be restored
// or removed (permissions): the case needs a look before a run writes into it.
StagingRecovery recoverStaging(const std::filesystem::path& dir,
                               StagingRecoveryOptions options = {});

}  // namespace isph
