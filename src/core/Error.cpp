#include "core/Error.hpp"

#include "core/ParallelRun.hpp"

#include <fmt/format.h>

#include <atomic>
#include <iostream>

namespace isph {

namespace {
std::atomic<int> nWarnings{0};
}

std::string SourceLocation::str() const {
  if (!file) return "<unknown>";
  if (line <= 0) return *file;
  if (column <= 0) return fmt::format("{}, line {}", *file, line);
  return fmt::format("{}, line {}, column {}", *file, line, column);
}

FatalError::FatalError(std::string message, SourceLocation where)
    : std::runtime_error(std::move(message)), where_(std::move(where)) {}

std::string FatalError::report() const {
  if (where_.file) {
    return fmt::format("\n--> FATAL IO ERROR:\n{}\n\nfile: {}.\n", what(), where_.str());
  }
  return fmt::format("\n--> FATAL ERROR:\n{}\n", what());
}

void fatalError(std::string message) { throw FatalError(std::move(message)); }

void fatalIOError(const SourceLocation& where, std::string message) {
  throw FatalError(std::move(message), where);
}

void warning(const std::string& message, const SourceLocation& where) {
  ++nWarnings;
  if (!isMasterRank()) return;  // as the log: rank 0's (every rank reads the same dictionaries)
  std::cout.flush();
  if (where.file) {
    std::cerr << fmt::format("--> Warning: {}\n    file: {}.\n", message, where.str());
  } else {
    std::cerr << fmt::format("--> Warning: {}\n", message);
  }
  std::cerr.flush();
}

int warningCount() { return nWarnings.load(); }

}  // namespace isph
