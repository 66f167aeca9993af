#pragma once
// A ParaView data collection, VTK/<case>.pvd: one <DataSet timestep="t" file="..."/> per
// converted time, in time order, so that ParaView opens the whole animation at once.
// Converting some times again merges them into the collection already there: an entry for a
// time replaces the old one of that time, and entries whose file no longer exists are dropped.
#include <filesystem>
#include <string>
#include <vector>

namespace isph {

struct PvdEntry {
  std::string time;  // the time directory's name, written as the timestep
  std::string file;  // relative to the .pvd's folder
};

// The entries of an existing collection (empty when `pvd` does not exist); FatalError naming
// the file when it is not a readable collection.
std::vector<PvdEntry> readPvd(const std::filesystem::path& pvd);

// `existing` with `added` merged in, entries whose file is missing from `folder` dropped,
// sorted by time value.
std::vector<PvdEntry> mergePvd(std::vector<PvdEntry> existing, const std::vector<PvdEntry>& added,
                               const std::filesystem::path& folder);

std::string pvdText(const std::vector<PvdEntry>& entries);

// readPvd + mergePvd + an atomic write; returns the entries written.
std::vector<PvdEntry> updatePvd(const std::filesystem::path& pvd, const std::vector<PvdEntry>& added);

}  // namespace isph
