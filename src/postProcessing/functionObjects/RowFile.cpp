#include "postProcessing/functionObjects/RowFile.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/ReadFile.hpp"

namespace isph {

namespace fs = std::filesystem;

RowFile::RowFile(fs::path file, std::string owner) : file_(std::move(file)), owner_(std::move(owner)) {}

RowFile::~RowFile() {
  if (fd_ >= 0) ::close(fd_);
}

void RowFile::write(const std::string& lines) {
  auto failed = [&](const std::string& reason) {
    fatalError(fmt::format("{}: cannot write {}: {}{}", owner_, file_.string(), reason,
                           fd_ >= 0 ? " (the rows before are whole)" : " (the file is as it was)"));
  };
  if (fd_ < 0) {
    std::error_code ec;
    fs::create_directories(file_.parent_path(), ec);
    if (ec) failed(ec.message());
    try {
      writeFileAtomic(file_, lines);
    } catch (const FatalError& e) {
      failed(e.what());
    }
    fd_ = ::open(file_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd_ < 0) failed(std::strerror(errno));
    return;
  }
  const off_t before = ::lseek(fd_, 0, SEEK_END);
  std::size_t done = 0;
  while (done < lines.size()) {
    const ssize_t n = ::write(fd_, lines.data() + done, lines.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const std::string reason = n < 0 ? std::strerror(errno) : "nothing written";
      if (before >= 0 && ::ftruncate(fd_, before) != 0) {
        failed(reason + fmt::format("; and the part of a row written could not be cut off: {}", std::strerror(errno)));
      }
      failed(reason);
    }
    done += static_cast<std::size_t>(n);
  }
}

void dropHalfRows(const fs::path& dir, const std::string& fileName) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const fs::path file = it->path() / fileName;
    if (!fs::is_regular_file(file)) continue;
    const std::string text = readFileBytes(file);
    if (text.empty() || text.back() == '\n') continue;
    const std::size_t keep = text.rfind('\n') == std::string::npos ? 0 : text.rfind('\n') + 1;
    fs::resize_file(file, keep);
    info("Dropped the half row at the end of {} ({} bytes without a newline, left by a run stopped while it "
         "wrote)",
         file.string(), text.size() - keep);
  }
}

}  // namespace isph
