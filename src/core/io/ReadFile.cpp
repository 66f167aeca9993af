// readFileBytes with POSIX open/fstat/read.
#include "core/io/ReadFile.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "core/Error.hpp"

namespace isph {

namespace {

[[noreturn]] void readError(const std::filesystem::path& file, int err) {
  fatalError(fmt::format("cannot read file {}: {}", file.string(),
                         std::error_code(err, std::generic_category()).message()));
}

const char* fileType(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

class OpenFile {
 public:
  explicit OpenFile(const std::filesystem::path& file) : file_(file) {
    // O_NONBLOCK: opening a FIFO without a writer must not hang before fstat refuses it.
    fd_ = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd_ < 0) readError(file, errno);
    if (::fstat(fd_, &st_) != 0) fail(errno);
    if (S_ISDIR(st_.st_mode)) fail(EISDIR);
    if (!S_ISREG(st_.st_mode)) {
      closeNow();
      fatalError(fmt::format("cannot read file {}: it is {}, not a regular file", file.string(),
                             fileType(st_.st_mode)));
    }
  }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  ~OpenFile() { closeNow(); }

  std::size_t size() const { return static_cast<std::size_t>(st_.st_size); }

  std::string read(std::size_t maxBytes) {
    std::string out;
    out.resize(size() < maxBytes ? size() : maxBytes);
    std::size_t got = 0;
    while (got < out.size()) {  // until full, or EOF if the file shrank meanwhile
      const ssize_t n = ::read(fd_, out.data() + got, out.size() - got);
      if (n < 0) {
        if (errno == EINTR || errno == EAGAIN) continue;
        fail(errno);
      }
      if (n == 0) break;
      got += static_cast<std::size_t>(n);
    }
    out.resize(got);
    return out;
  }

 private:
  void closeNow() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  [[noreturn]] void fail(int err) {
    closeNow();
    readError(file_, err);
  }

  std::filesystem::path file_;
  int fd_ = -1;
  struct stat st_ {};
};

}  // namespace

std::string bytesText(double bytes) {
  if (bytes >= 1024.0 * 1024 * 1024)
    return fmt::format("{:.3g} GiB", bytes / (1024.0 * 1024 * 1024));
  if (bytes >= 1024.0 * 1024) return fmt::format("{:.3g} MiB", bytes / (1024.0 * 1024));
  if (bytes >= 1024.0) return fmt::format("{:.3g} KiB", bytes / 1024.0);
  return fmt::format("{:.0f} bytes", bytes);
}

std::string readFileBytes(const std::filesystem::path& file, std::size_t maxBytes) {
  OpenFile in(file);
  return in.read(maxBytes);
}

std::string readWholeFile(const std::filesystem::path& file, std::size_t limit,
                          std::string_view what) {
  OpenFile in(file);
  if (in.size() > limit) {
    fatalError(
        fmt::format("cannot read file {} as {}: it holds {}, more than the {} such a file may hold",
                    file.string(), what, bytesText(static_cast<double>(in.size())),
                    bytesText(static_cast<double>(limit))));
  }
  return in.read(limit);
}

}  // namespace isph
