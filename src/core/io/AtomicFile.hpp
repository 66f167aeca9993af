#pragma once
// Crash-safe output: files and whole directories (a time directory) are written under a
// hidden temporary name, flushed to disk and published with one rename, so that a reader
// or a restart sees the old content or the new one, never a half-written one; a directory is
// removed by renaming it out of view first. Hidden names: StagingNames.hpp.
//
// What remains if the process dies (or the machine loses power) at each point:
//  writeFileAtomic
//   - while writing or syncing the temporary ".<name>.tmp.<pid>.<n>@<host>": the target is
//     untouched; a hidden temporary file remains.
//   - after the rename: the new file is complete (its data was fsync'ed before the rename).
//  StagedDirectory
//   - before commit(): only the hidden staging directory ".<name>.tmp.<pid>@<host>" exists;
//     the target (if any) is untouched.
//   - in commit(), between renaming an existing target aside (".<name>.old.<pid>@<host>") and
//     renaming the staging directory in: the target name is briefly absent; the previous,
//     complete content is under ".old." and the new, complete content under ".tmp.".
//   - after the rename-in, while the ".old." is being deleted: the target is new and
//     complete; what is left of the ".old." remains.
//  removeDirectoryAtomically
//   - after the rename to ".<name>.trash.<pid>@<host>": the directory is out of view (a time
//     listing no longer has it) while its content is being deleted.
// recoverStaging (StagingRecovery.hpp), which every application runs at start, renames an
// orphaned ".old." back to <name> and deletes the rest. Every staging name starts with '.',
// so listings that skip hidden entries (the time directory scan) never see them.
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

// Remove the directory `dir` (a time directory purged by purgeWrite) crash-safely: it is
// first renamed to the hidden ".<name>.trash.<pid>@<host>" (and the folder flushed), then
// deleted; a kill during the deletion leaves nothing that looks like a time. FatalError if it
// cannot be renamed or deleted.
void removeDirectoryAtomically(const std::filesystem::path& dir);

// fsync a directory (after renames in it); a file system that cannot is ignored.
void syncDirectory(const std::filesystem::path& dir);

namespace detail {
// The two halves of writeFileAtomic, separate so that tests can stop in between.
// Writes and fsyncs `content` to the hidden ".<name>.tmp.<pid>.<n>@<host>" next to `file`;
// returns it.
std::filesystem::path writeStagingFile(const std::filesystem::path& file, std::string_view content);
// Renames `staged` over `file` and fsyncs the folder.
void publishStagingFile(const std::filesystem::path& staged, const std::filesystem::path& file);
}  // namespace detail

}  // namespace isph
