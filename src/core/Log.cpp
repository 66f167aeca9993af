#include "core/Log.hpp"

#include "core/ParallelRun.hpp"

#include <iostream>
#include <mutex>
#include <set>

namespace isph {

namespace {
std::mutex logMutex;
std::set<std::string> echoed;
}  // namespace

void infoLine(std::string_view line) {
  if (!isMasterRank()) return;  // a parallel run's log is rank 0's
  std::lock_guard lock(logMutex);
  std::cout << line << '\n';
}

bool echoDefaultOnce(const std::string& key, const std::string& line) {
  {
    std::lock_guard lock(logMutex);
    if (!echoed.insert(key).second) return false;
  }
  infoLine(line);
  return true;
}

}  // namespace isph
