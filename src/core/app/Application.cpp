#include "core/app/Application.hpp"

#include <fmt/format.h>

#include <exception>
#include <iostream>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/ParallelRun.hpp"
#include "core/app/Banner.hpp"

namespace isph {

namespace {

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
  try {
    const ArgList args(spec, argc, argv);
    const bool banner = spec.banner && isMasterRank();  // a parallel run's log is rank 0's
    if (banner) std::cout << isph::banner(args) << '\n';
    body(args);
    if (banner) std::cout << "\nEnd\n" << std::flush;
    return 0;
  } catch (const HelpRequested& help) {
    std::cout << help.usage << std::flush;
    return 0;
  } catch (const FatalError& e) {
    return failed(e.report());
  } catch (const std::exception& e) {
    return failed(fmt::format("\n--> FATAL ERROR:\n{}\n", e.what()));
  }
}

}  // namespace isph
