#include "core/app/Application.hpp"

#include <exception>
#include <iostream>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/app/Banner.hpp"

namespace isph {

int runApplication(const ApplicationSpec& spec, int argc, const char* const* argv,
                   const std::function<void(const ArgList&)>& body) {
  try {
    const ArgList args(spec, argc, argv);
    if (spec.banner) std::cout << banner(args) << '\n';
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
  } catch (const std::exception& e) {
    std::cout.flush();
    std::cerr << "\n--> FATAL ERROR:\n" << e.what() << "\n\nisphLandslide exiting\n" << std::flush;
    return 1;
  }
}

}  // namespace isph
