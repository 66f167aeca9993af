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
}  // namespace

std::string readFileBytes(const std::filesystem::path& file, std::size_t maxBytes) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) readError(file, errno);
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    readError(file, err);
  }
  if (S_ISDIR(st.st_mode)) {
    ::close(fd);
    readError(file, EISDIR);
  }
  std::string out;
  const auto size = static_cast<std::size_t>(st.st_size);
  out.resize(size < maxBytes ? size : maxBytes);
  std::size_t got = 0;
  while (got < out.size()) {  // until full, or EOF if the file shrank meanwhile
    const ssize_t n = ::read(fd, out.data() + got, out.size() - got);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      readError(file, err);
    }
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  out.resize(got);
  return out;
}

}  // namespace isph
