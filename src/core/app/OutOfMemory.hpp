#pragma once
// Running out of memory is a fatal error that says what was being built, not an abort that
// loses the log. Code that allocates much says what it builds for as long as it does:
//
//   const Building building(fmt::format("the lattice sites of region '{}'", name));
//
// runApplication turns a std::bad_alloc into "out of memory while building <the innermost
// one>", with the peak memory used, after flushing the log; installOutOfMemoryHandler makes
// the same of one thrown where no handler can catch it (inside an OpenMP parallel loop, where
// it would call std::terminate).
#include <string>

namespace isph {

class Building {
 public:
  explicit Building(std::string what);
  Building(const Building&) = delete;
  Building& operator=(const Building&) = delete;
  ~Building();

  // The innermost thing being built, or, while an exception unwinds them, the innermost one
  // it left; "" when none (set and read by the main thread).
  static std::string current();

 private:
  int uncaught_;
};

// "out of memory while building X (peak resident memory N MB ...)": the message for bad_alloc.
std::string outOfMemoryMessage();

// A std::terminate handler that reports a std::bad_alloc as outOfMemoryMessage() on stderr,
// flushes stdout (the log) and exits with status 1; anything else aborts as before.
void installOutOfMemoryHandler();

}  // namespace isph
