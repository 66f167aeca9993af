#pragma once
// Crash-safe output: files and whole directories (a time directory) are written under a
// hidden temporary name, flushed to disk and published with one rename, so that a reader
// or a restart sees the old content or the new one, never a half-written one.
//
// What remains if the process dies (or the machine loses power) at each point:
//  writeFileAtomic
//   - while writing or syncing the temporary ".<name>.tmp.<pid>": the target is untouched;
//     a hidden temporary file remains (removeStaleStaging deletes it).
//   - after the rename: the new file is complete (its data was fsync'ed before the rename).
//  StagedDirectory
//   - before commit(): only the hidden staging directory ".<name>.tmp.<pid>" exists; the
//     target (if any) is untouched.
//   - in commit(), between renaming an existing target aside (".<name>.old.<pid>") and
//     renaming the staging directory in: the target name is briefly absent; the previous,
//     complete content is under ".<name>.old.<pid>" and the new, complete content under
//     ".<name>.tmp.<pid>". removeStaleStaging renames such an orphaned ".old." back to
//     <name> (it was a committed directory) and deletes the ".tmp.".
//   - after the rename-in, while the ".old." is being deleted: the target is new and
//     complete; removeStaleStaging deletes what is left of the ".old.".
// Every staging name starts with '.', so listings that skip hidden entries (the time
// directory scan) never see them.
#include <filesystem>
#include <string_view>

namespace isph {

// Write `content` to `file` through a temporary file in the same folder (same-filesystem rename),
// flushed with fsync, then renamed over `file`; readers see the old or the new file, never half.
void writeFileAtomic(const std::filesystem::path& file, std::string_view content);

// Builds a directory under a hidden temporary name next to `target` (".<name>.tmp.<pid>") and
// publishes it with one rename in commit(); the destructor removes an uncommitted staging dir.
class StagedDirectory {
 public:
  explicit StagedDirectory(std::filesystem::path target);
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;
  ~StagedDirectory();

  // Where to write the content (target() once committed).
  const std::filesystem::path& path() const;
  const std::filesystem::path& target() const;
  bool committed() const { return committed_; }
  void commit();  // fsync files+dir, then rename; an existing target is first renamed aside
                  // (".<name>.old.<pid>") and removed after the new one is in place

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

// Remove leftovers of interrupted runs (".*.tmp.*" and ".*.old.*" entries) in `dir`; returns how
// many. An ".<name>.old.<pid>" directory whose <name> is missing (a commit interrupted between
// its two renames) is renamed back to <name> instead, and counted too. Call it at start-up,
// while no other process writes into `dir`. A missing `dir` gives 0.
int removeStaleStaging(const std::filesystem::path& dir);

namespace detail {
// The two halves of writeFileAtomic, separate so that tests can stop in between.
// Writes and fsyncs `content` to the hidden ".<name>.tmp.<pid>.<n>" next to `file`; returns it.
std::filesystem::path writeStagingFile(const std::filesystem::path& file, std::string_view content);
// Renames `staged` over `file` and fsyncs the folder.
void publishStagingFile(const std::filesystem::path& staged, const std::filesystem::path& file);
// ".<name>.<kind>.<pid>" next to `target` (kind "tmp" or "old").
std::filesystem::path stagingName(const std::filesystem::path& target, std::string_view kind);
}  // namespace detail

}  // namespace isph
