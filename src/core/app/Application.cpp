#include "core/app/Application.hpp"

#include <fmt/format.h>

#include <exception>
#include <iostream>
#include <memory>
#include <new>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/ParallelRun.hpp"
#include "core/app/Banner.hpp"
#include "core/app/DefaultThreads.hpp"
#include "core/app/OutOfMemory.hpp"
#include "core/io/CaseLock.hpp"
#include "core/io/StagingRecovery.hpp"
#include "core/time/StopSignal.hpp"

namespace isph {

namespace {

// Restore or clear what interrupted runs left in the case, and say so: in the log, or on
// stderr for the tools whose stdout is parsed. In a parallel run rank 0 does it (with the
// processor directories) while the others wait: the ranks would race on the same leftovers.
void recoverCase(const ApplicationSpec& spec, const ArgList& args) {
  if (spec.recovery == CaseRecovery::none) return;
  StagingRecovery r;
  if (isMasterRank()) {
    r = recoverStaging(args.casePath(), {.ownsForeignHosts = spec.recovery == CaseRecovery::allHosts});
  }
  agreeOverRanks(0);  // (a barrier in a parallel run: no rank reads the case before it is recovered)
  if (r.log.empty()) return;
  std::ostream& out = spec.banner ? std::cout : std::cerr;
  out << fmt::format("Interrupted writes in the case: {} restored, {} removed, {} left alone\n", r.restored,
                     r.removed, r.leftAlone);
  for (const auto& line : r.log) out << line << '\n';
  out << (spec.banner ? "\n" : "") << std::flush;
}

// The case lock of an application that writes time directories (CaseLock.hpp), taken before the
// recovery (which owns what other hosts left: only with the lock is no one else writing), by
// rank 0 of a parallel run; every rank ends when it is refused.
std::unique_ptr<CaseLock> lockCase(const ApplicationSpec& spec, const ArgList& args) {
  if (spec.recovery != CaseRecovery::allHosts) return nullptr;
  std::unique_ptr<CaseLock> lock;
  std::string taken;
  try {
    if (isMasterRank()) lock = std::make_unique<CaseLock>(args.casePath(), args.commandLine(), taken);
  } catch (const FatalError&) {
    agreeOverRanks(1);
    throw;
  }
  if (agreeOverRanks(0) != 0) fatalError("the case is in use by another application (rank 0 says which)");
  if (!taken.empty()) (spec.banner ? std::cout : std::cerr) << taken << "\n\n" << std::flush;
  return lock;
}

// The error on stderr (from the rank that met it, named in a parallel run), then the exit
// status 1; in a parallel run every rank ends, or the others would wait for this one.
int failed(const std::string& report) {
  std::cout.flush();
  const ParallelRun& run = parallelRun();
  const std::string rank = run.nProcs > 1 ? fmt::format("[rank {}] ", run.rank) : std::string();
  std::cerr << rank << report << "\n" << rank << "isphLandslide exiting\n" << std::flush;
  if (run.nProcs > 1 && run.abort) run.abort(1);
  return 1;
}

}  // namespace

int runApplication(const ApplicationSpec& spec, int argc, const char* const* argv,
                   const std::function<void(const ArgList&)>& body) {
  installOutOfMemoryHandler();
  applyDefaultThreadCount();
  try {
    const ArgList args(spec, argc, argv);
    const bool banner = spec.banner && isMasterRank();  // a parallel run's log is rank 0's
    if (banner) std::cout << isph::banner(args) << '\n';
    const std::unique_ptr<CaseLock> lock = lockCase(spec, args);
    recoverCase(spec, args);
    body(args);
    // "End" closes the log of a finished run only: runApplication (etc/RunFunctions) skips a
    // step whose log ends so, and runs again one stopped by a signal.
    if (banner && !stopSignal::caught()) std::cout << "\nEnd\n" << std::flush;
    return 0;
  } catch (const HelpRequested& help) {
    std::cout << help.usage << std::flush;
    return 0;
  } catch (const FatalError& e) {
    return failed(e.report());
  } catch (const std::bad_alloc&) {
    return failed(fmt::format("\n--> FATAL ERROR:\n{}\n", outOfMemoryMessage()));
  } catch (const std::exception& e) {
    return failed(fmt::format("\n--> FATAL ERROR:\n{}\n", e.what()));
  }
}

}  // namespace isph
