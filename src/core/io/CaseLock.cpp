#include "core/io/CaseLock.hpp"

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>
#include <csignal>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "core/Error.hpp"
#include "core/io/ReadFile.hpp"
#include "core/io/StagingNames.hpp"

namespace isph {

namespace fs = std::filesystem;

namespace {

// Field 22 of /proc/<pid>/stat (the start in clock ticks after boot), "" when unknown.
std::string processStart(long pid) {
  std::ifstream in(fmt::format("/proc/{}/stat", pid));
  std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = stat.rfind(')');  // (the command name may hold spaces)
  if (close == std::string::npos) return {};
  std::istringstream fields(stat.substr(close + 1));
  std::string field;
  for (int i = 3; i <= 22 && fields >> field; ++i) {
    if (i == 22) return field;
  }
  return {};
}

// The lines "key value" of a lock file.
std::map<std::string, std::string> parseLock(const std::string& text) {
  std::map<std::string, std::string> entries;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto space = line.find(' ');
    const auto value = line.find_first_not_of(' ', space);
    if (space == std::string::npos || value == std::string::npos) continue;
    entries[line.substr(0, space)] = line.substr(value);
  }
  return entries;
}

// Whether the holder of a lock (same host) has ended: its pid is gone, or is another process's.
bool holderEnded(const std::map<std::string, std::string>& lock) {
  long pid = 0;
  try {
    pid = std::stol(lock.count("pid") ? lock.at("pid") : "0");
  } catch (const std::exception&) {
    return true;  // (a lock cut short by a crash while it was written)
  }
  if (pid <= 0) return true;
  if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno != EPERM) return true;
  const std::string start = processStart(pid);
  return lock.count("processStart") && !start.empty() && lock.at("processStart") != start;
}

std::string holder(const std::map<std::string, std::string>& lock) {
  auto get = [&](const char* key) { return lock.count(key) ? lock.at(key) : std::string("?"); };
  return fmt::format("process {} on host {}, started {}: {}", get("pid"), get("host"), get("started"), get("command"));
}

}  // namespace

CaseLock::CaseLock(const fs::path& caseDir, const std::string& command, std::string& taken)
    : file_(caseDir / fileName) {
  taken.clear();
  const long pid = static_cast<long>(::getpid());
  content_ = fmt::format("pid          {}\nhost         {}\nprocessStart {}\nstarted      {:%Y-%m-%d %H:%M:%S} UTC\n"
                         "command      {}\n",
                         pid, thisHost(), processStart(pid),
                         fmt::gmtime(std::time(nullptr)), command);
  const fs::path staged = stagingName(file_, "tmp");
  {
    std::ofstream out(staged);
    out << content_;
    if (!out.flush()) {
      fatalError(fmt::format("cannot write the case lock {}: {}", staged.string(), std::strerror(errno)));
    }
  }
  struct Unlink {
    fs::path p;
    ~Unlink() { ::unlink(p.c_str()); }
  } removeStaged{staged};
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (::link(staged.c_str(), file_.c_str()) == 0) return;
    if (errno != EEXIST) {
      fatalError(fmt::format("cannot create the case lock {}: {}", file_.string(), std::strerror(errno)));
    }
    std::string existing;
    try {
      existing = readFileBytes(file_);
    } catch (const FatalError&) {
      continue;  // (its holder removed it meanwhile)
    }
    const auto lock = parseLock(existing);
    const bool thisHostsLock = lock.count("host") && lock.at("host") == thisHost();
    if (!thisHostsLock || !holderEnded(lock)) {
      fatalError(fmt::format(
          "the case {} is in use: {} holds {} ({}).\nTwo applications that write time directories must not run on "
          "one case: wait for it to end, or stop it.{}",
          caseDir.string(), lock.count("command") ? lock.at("command") : "an application", file_.string(),
          holder(lock),
          thisHostsLock ? std::string()
                        : fmt::format(" (Another host's process cannot be checked from here: if it has ended, "
                                      "remove {}.)",
                                      file_.string())));
    }
    // Gone: set it aside under a name of our own, and take it over only if it is still the one
    // read (another process may have taken it over meanwhile: then put that one back).
    const fs::path aside = stagingName(file_, "trash");
    if (::rename(file_.c_str(), aside.c_str()) != 0) continue;
    std::string moved;
    try {
      moved = readFileBytes(aside);
    } catch (const FatalError&) {
    }
    if (moved != existing) {
      ::link(aside.c_str(), file_.c_str());
      ::unlink(aside.c_str());
      continue;
    }
    ::unlink(aside.c_str());
    taken = fmt::format("Took over the case lock {} of an application that has ended ({})", file_.string(),
                        holder(lock));
  }
  fatalError(fmt::format("cannot take the case lock {}: other processes are taking it at the same time",
                         file_.string()));
}

CaseLock::~CaseLock() {
  std::error_code ec;
  try {
    if (readFileBytes(file_) == content_) fs::remove(file_, ec);
  } catch (...) {  // (removed by hand: nothing to do)
  }
}

}  // namespace isph
