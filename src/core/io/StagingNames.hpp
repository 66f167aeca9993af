#pragma once
// The hidden names under which output is staged, set aside or thrown away next to its target
// (AtomicFile.hpp), and who made them:
//
//   .<name>.tmp.<pid>[.<serial>]@<host>    a file or directory being written
//   .<name>.old.<pid>@<host>               a directory replaced by a commit, being removed
//   .<name>.trash.<pid>@<host>             a directory being removed (a purged time)
//
// The process id and host say whether the writer may still be at work (StagingRecovery.hpp).
// Names without "@<host>" (written before the host was recorded) count as of this host.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace isph {

struct StagingEntry {
  std::string target;  // <name>
  std::string kind;    // tmp, old or trash
  long pid = 0;
  std::string host;  // empty: this host
};

// ".<name>.<kind>.<pid>[.<serial>]@<host>" next to `target` (a trailing '/' ignored).
std::filesystem::path stagingName(const std::filesystem::path& target, std::string_view kind,
                                  std::optional<unsigned> serial = {});

// The parts of a staging name (a file name, not a path), or nullopt when it is none.
std::optional<StagingEntry> parseStagingName(std::string_view name);

// This machine's host name as staging names record it.
const std::string& thisHost();

}  // namespace isph
