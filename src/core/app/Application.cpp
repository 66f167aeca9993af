#include "core/app/Application.hpp"

#include <fmt/format.h>

#include <exception>
#include <iostream>
#include <new>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/app/Banner.hpp"
#include "core/app/OutOfMemory.hpp"
#include "core/io/StagingRecovery.hpp"

namespace isph {

namespace {

// Restore or clear what interrupted runs left in the case, and say so: in the log, or on
// stderr for the tools whose stdout is parsed.
void recoverCase(const ApplicationSpec& spec, const ArgList& args) {
  if (spec.recovery == CaseRecovery::none) return;
  const StagingRecovery r =
      recoverStaging(args.casePath(), {.ownsForeignHosts = spec.recovery == CaseRecovery::allHosts});
  if (r.log.empty()) return;
  std::ostream& out = spec.banner ? std::cout : std::cerr;
  out << fmt::format("Interrupted writes in the case: {} restored, {} removed, {} left alone\n", r.restored,
                     r.removed, r.leftAlone);
  for (const auto& line : r.log) out << line << '\n';
  out << (spec.banner ? "\n" : "") << std::flush;
}

}  // namespace

int runApplication(const ApplicationSpec& spec, int argc, const char* const* argv,
                   const std::function<void(const ArgList&)>& body) {
  installOutOfMemoryHandler();
  try {
    const ArgList args(spec, argc, argv);
    if (spec.banner) std::cout << banner(args) << '\n';
    recoverCase(spec, args);
    body(args);
    if (spec.banner) std::cout << "\nEnd\n" << std::flush;
    return 0;
  } catch (const HelpRequested& help) {
    std::cout << help.usage << std::flush;
    return 0;
  } catch (const FatalError& e) {
    std::cout.flush();
    std::cerr << e.report() << "\nisphLandslide exiting\n" << std::flush;
    return 1;
  } catch (const std::bad_alloc&) {
    std::cout.flush();
    std::cerr << "\n--> FATAL ERROR:\n" << outOfMemoryMessage() << "\n\nisphLandslide exiting\n" << std::flush;
    return 1;
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << "\n--> FATAL ERROR:\n" << e.what() << "\n\nisphLandslide exiting\n" << std::flush;
    return 1;
  }
}

}  // namespace isph
