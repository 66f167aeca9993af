#include "core/app/OutOfMemory.hpp"

#include <fmt/format.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <vector>

#include "core/app/ResourceUsage.hpp"

namespace isph {

namespace {

std::vector<std::string>& stack() {
  static std::vector<std::string> s;
  return s;
}

// The innermost Building that an exception unwound (its catch comes after the destructors).
std::string& left() {
  static std::string s;
  return s;
}

std::string addressSpaceLimit() {
  rlimit limit{};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return "";
  return fmt::format(", within an address-space limit (ulimit -v) of {:.0f} MB",
                     static_cast<double>(limit.rlim_cur) / (1024.0 * 1024.0));
}

[[noreturn]] void onTerminate() {
  if (const std::exception_ptr e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::bad_alloc&) {
      std::cout.flush();
      std::fflush(nullptr);
      std::cerr << "\n--> FATAL ERROR:\n"
                << outOfMemoryMessage() << "\n\nisphLandslide exiting\n"
                << std::flush;
      std::_Exit(1);
    } catch (...) {
    }
  }
  std::cout.flush();
  std::abort();
}

}  // namespace

Building::Building(std::string what) : uncaught_(std::uncaught_exceptions()) {
  left().clear();  // a new stage: an earlier exception was handled
  stack().push_back(std::move(what));
}

Building::~Building() {
  if (std::uncaught_exceptions() > uncaught_ && left().empty()) left() = stack().back();
  stack().pop_back();
}

std::string Building::current() { return stack().empty() ? left() : stack().back(); }

std::string outOfMemoryMessage() {
  const std::string what = Building::current();
  return fmt::format(
      "out of memory{}{} (peak resident memory {:.0f} MB{}).\n    Free memory, or make the "
      "case smaller (a coarser spacing, fewer particles).",
      what.empty() ? "" : " while building ", what, peakResidentMegabytes(), addressSpaceLimit());
}

void installOutOfMemoryHandler() { std::set_terminate(onTerminate); }

}  // namespace isph
