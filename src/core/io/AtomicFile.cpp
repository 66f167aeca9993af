// Atomic file and directory publication with POSIX open/write/fsync/rename.
#include "core/io/AtomicFile.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <string>
#include <system_error>
#include <vector>

#include "core/Error.hpp"
#include "core/io/StagingNames.hpp"

namespace isph {

namespace fs = std::filesystem;

namespace {

std::string errnoText(int err) { return std::error_code(err, std::generic_category()).message(); }

// The folder that holds `p` ("." for a bare relative name).
fs::path folderOf(const fs::path& p) {
  return p.parent_path().empty() ? fs::path(".") : p.parent_path();
}

// "0.1/" and "0.1" name the same directory.
fs::path withoutTrailingSlash(fs::path p) {
  if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();
  return p;
}

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  // Close now and report the error close() gives (NFS reports write errors here).
  int close() {
    const int rc = ::close(fd_);
    fd_ = -1;
    return rc == 0 ? 0 : errno;
  }

 private:
  int fd_;
};

void fsyncPath(const fs::path& p, bool directory) {
  Fd fd(::open(p.c_str(), O_RDONLY | O_CLOEXEC | (directory ? O_DIRECTORY : 0)));
  if (fd.get() < 0) {
    const int err = errno;
    fatalError(fmt::format("cannot open {} to flush it to disk: {}", p.string(), errnoText(err)));
  }
  if (::fsync(fd.get()) != 0) {
    const int err = errno;
    // EINVAL/EROFS: this file system cannot sync (a directory); nothing more can be done.
    if (err != EINVAL && err != EROFS) {
      fatalError(fmt::format("cannot flush {} to disk: {}", p.string(), errnoText(err)));
    }
  }
}

void renameOrFail(const fs::path& from, const fs::path& to) {
  if (::rename(from.c_str(), to.c_str()) != 0) {
    const int err = errno;
    fatalError(
        fmt::format("cannot rename {} to {}: {}", from.string(), to.string(), errnoText(err)));
  }
}

// Recursively fsync every file and directory under `dir`, then `dir` itself.
void fsyncTree(const fs::path& dir) {
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::file_status st = it->symlink_status();
    if (fs::is_regular_file(st)) fsyncPath(it->path(), false);
    if (fs::is_directory(st)) fsyncPath(it->path(), true);
  }
  if (ec)
    fatalError(fmt::format("cannot list {} to flush it to disk: {}", dir.string(), ec.message()));
  fsyncPath(dir, true);
}

}  // namespace

namespace detail {

fs::path writeStagingFile(const fs::path& file, std::string_view content) {
  // A per-process counter keeps two threads writing the same file apart.
  static std::atomic<unsigned> counter{0};
  const fs::path tmp = stagingName(file, "tmp", counter++);

  Fd fd(::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
  if (fd.get() < 0) {
    const int err = errno;
    fatalError(fmt::format("cannot create {} (to write {}): {}", tmp.string(), file.string(),
                           errnoText(err)));
  }
  auto fail = [&](const std::string& what, int err) {
    ::unlink(tmp.c_str());
    fatalError(fmt::format("cannot write {} ({} failed): {}", file.string(), what, errnoText(err)));
  };
  const char* data = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    const ssize_t n = ::write(fd.get(), data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("write", errno);
    }
    if (n == 0) fail("write", ENOSPC);
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd.get()) != 0) fail("fsync", errno);
  if (const int err = fd.close(); err != 0) fail("close", err);
  return tmp;
}

void publishStagingFile(const fs::path& staged, const fs::path& file) {
  if (::rename(staged.c_str(), file.c_str()) != 0) {
    const int err = errno;
    ::unlink(staged.c_str());
    fatalError(
        fmt::format("cannot rename {} to {}: {}", staged.string(), file.string(), errnoText(err)));
  }
  fsyncPath(folderOf(file), true);
}

}  // namespace detail

void writeFileAtomic(const fs::path& file, std::string_view content) {
  detail::publishStagingFile(detail::writeStagingFile(file, content), file);
}

// ---- StagedDirectory ------------------------------------------------------------------

StagedDirectory::StagedDirectory(fs::path target)
    : target_(withoutTrailingSlash(std::move(target))),
      staging_(stagingName(target_, "tmp")) {
  if (target_.filename().empty() || target_.filename() == "." || target_.filename() == "..") {
    fatalError(fmt::format("cannot stage directory {}: it has no name", target_.string()));
  }
  std::error_code ec;
  fs::remove_all(staging_, ec);  // a leftover of this pid (an earlier run, or an exception)
  if (ec)
    fatalError(fmt::format("cannot remove the old staging directory {}: {}", staging_.string(),
                           ec.message()));
  if (!fs::create_directory(staging_, ec) || ec) {
    fatalError(fmt::format("cannot create the staging directory {}: {}", staging_.string(),
                           ec ? ec.message() : std::string("it already exists")));
  }
}

StagedDirectory::~StagedDirectory() {
  if (!committed_) {
    std::error_code ec;
    fs::remove_all(staging_, ec);  // best effort; recoverStaging clears what remains
  }
}

const fs::path& StagedDirectory::path() const { return committed_ ? target_ : staging_; }

const fs::path& StagedDirectory::target() const { return target_; }

void StagedDirectory::commit() {
  if (committed_) fatalError(fmt::format("directory {} is already committed", target_.string()));
  fsyncTree(staging_);

  std::error_code ec;
  const bool replacing = fs::exists(fs::symlink_status(target_, ec));
  const fs::path aside = stagingName(target_, "old");
  if (replacing) {
    fs::remove_all(aside, ec);
    renameOrFail(target_, aside);
  }
  if (::rename(staging_.c_str(), target_.c_str()) != 0) {
    const int err = errno;
    if (replacing) ::rename(aside.c_str(), target_.c_str());  // put the old one back
    fatalError(fmt::format("cannot rename {} to {}: {}", staging_.string(), target_.string(),
                           errnoText(err)));
  }
  committed_ = true;
  fsyncPath(folderOf(target_), true);
  if (replacing) {
    fs::remove_all(aside, ec);
    if (ec)
      fatalError(
          fmt::format("cannot remove the replaced directory {}: {}", aside.string(), ec.message()));
  }
}

// ---- removal ---------------------------------------------------------------------------

void syncDirectory(const fs::path& dir) { fsyncPath(dir, true); }

void removeDirectoryAtomically(const fs::path& dir) {
  const fs::path target = withoutTrailingSlash(dir);
  const fs::path trash = stagingName(target, "trash");
  std::error_code ec;
  fs::remove_all(trash, ec);  // a leftover of this pid
  renameOrFail(target, trash);
  fsyncPath(folderOf(target), true);
  fs::remove_all(trash, ec);
  if (ec) fatalError(fmt::format("cannot remove {} (renamed to {} for it): {}", target.string(), trash.string(), ec.message()));
}

}  // namespace isph
