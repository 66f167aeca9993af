#pragma once
// One writer of time directories per case: the applications that write them (the solver,
// particleMesh, decomposePar, reconstructPar: CaseRecovery::allHosts, ArgList.hpp) hold
// <case>/isphLock while they run, a file that says who:
//
//   pid          4711
//   host         node12
//   processStart 123456        (the process's start in clock ticks after boot: a reused pid is not it)
//   started      2026-12-06 07:30:00 UTC
//   command      isphLandslideFoam -case .
//
// A second such application on the case refuses to start, naming the holder. A lock whose
// process is gone (same host: no such pid, or one started at another moment, as kill -9 or a
// crash leaves it) is taken over with a line saying so; a lock of another host cannot be checked
// and is refused with the way to remove it. The lock is created with one link(), which fails if
// the file exists (no two can both create it, NFS included), and removed when its holder ends.
#include <filesystem>
#include <string>

namespace isph {

class CaseLock {
 public:
  // Takes <caseDir>/isphLock for `command`; FatalError when a live process holds it. `taken`
  // receives a line when a stale lock was taken over (empty otherwise), for the log.
  CaseLock(const std::filesystem::path& caseDir, const std::string& command, std::string& taken);
  ~CaseLock();  // removes the lock if it is still this process's
  CaseLock(const CaseLock&) = delete;
  CaseLock& operator=(const CaseLock&) = delete;

  static constexpr const char* fileName = "isphLock";

 private:
  std::filesystem::path file_;
  std::string content_;
};

}  // namespace isph
