// Restoring and clearing the leftovers of interrupted writes (staging names, StagingNames.hpp).
#include "core/io/StagingRecovery.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <system_error>

#include "core/Error.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/StagingNames.hpp"

namespace isph {

namespace fs = std::filesystem;

namespace {

// Whether the writer of `e` may still be running.
bool mayBeRunning(const StagingEntry& e, bool ownsForeignHosts) {
  if (!e.host.empty()) return !ownsForeignHosts;
  if (e.pid == static_cast<long>(::getpid())) return false;  // an earlier process with our pid
  return ::kill(static_cast<pid_t>(e.pid), 0) == 0 || errno == EPERM;
}

std::string writer(const StagingEntry& e) {
  return e.host.empty() ? fmt::format("process {}", e.pid)
                        : fmt::format("process {} on host {}", e.pid, e.host);
}

void removeOrFail(const fs::path& p) {
  std::error_code ec;
  fs::remove_all(p, ec);
  if (ec)
    fatalError(
        fmt::format("cannot remove {} (left by an interrupted run): {}", p.string(), ec.message()));
}

void recoverFolder(const fs::path& dir, const StagingRecoveryOptions& options,
                   StagingRecovery& out) {
  struct Found {
    fs::path path;
    StagingEntry entry;
  };
  std::vector<Found> found;
  std::vector<fs::path> folders;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (auto e = parseStagingName(name)) {
      found.push_back({it->path(), std::move(*e)});
    } else if (options.recursive) {
      std::error_code typeEc;
      if (it->is_directory(typeEc) && !it->is_symlink(typeEc)) folders.push_back(it->path());
    }
  }
  if (ec) fatalError(fmt::format("cannot list {}: {}", dir.string(), ec.message()));

  // Restore before removing: a replace caught between its renames left .old and .tmp.
  std::stable_partition(found.begin(), found.end(),
                        [](const Found& f) { return f.entry.kind == "old"; });
  for (const auto& [path, e] : found) {
    const std::string name = path.filename().string();
    if (mayBeRunning(e, options.ownsForeignHosts)) {
      ++out.leftAlone;
      out.log.push_back(fmt::format("    {} left alone: {} may still be writing it",
                                    (dir / name).string(), writer(e)));
      continue;
    }
    const fs::path original = dir / e.target;
    if (e.kind == "old" && !fs::exists(fs::symlink_status(original, ec))) {
      if (::rename(path.c_str(), original.c_str()) != 0) {
        const int err = errno;
        fatalError(fmt::format("cannot restore {} to {}: {}", path.string(), original.string(),
                               std::error_code(err, std::generic_category()).message()));
      }
      syncDirectory(dir);
      ++out.restored;
      out.log.push_back(
          fmt::format("    restored {} from {}: {} replaced it and was interrupted between its two "
                      "renames; this is the complete previous version",
                      original.string(), name, writer(e)));
      continue;
    }
    removeOrFail(path);
    ++out.removed;
    const char* what = e.kind == "tmp"     ? "an unfinished write, never published"
                       : e.kind == "trash" ? "the rest of an interrupted removal (a purged time)"
                                           : "the previous version of a replaced directory";
    out.log.push_back(fmt::format("    removed {}: {} of {} by {}", (dir / name).string(), what,
                                  e.target, writer(e)));
  }
  for (const auto& folder : folders) recoverFolder(folder, options, out);
}

}  // namespace

StagingRecovery recoverStaging(const fs::path& dir, StagingRecoveryOptions options) {
  StagingRecovery out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  recoverFolder(dir, options, out);
  return out;
}

}  // namespace isph
