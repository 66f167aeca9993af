#pragma once
// Fatal errors and warnings. User-input errors name the file, the line (and column),
// the keyword and what was expected; applications turn a FatalError into a message on
// stderr and a non-zero exit (see Application.hpp), never an assert or a core dump.
#include <memory>
#include <stdexcept>
#include <string>

namespace isph {

// Where a token or entry came from. `file` is shared by all tokens of one file.
struct SourceLocation {
  std::shared_ptr<const std::string> file;
  int line = 0;
  int column = 0;

  bool known() const { return file && line > 0; }
  // "system/controlDict, line 20, column 5" (or just the file name when line is unknown).
  std::string str() const;
};

class FatalError : public std::runtime_error {
 public:
  FatalError(std::string message, SourceLocation where = {});
  const SourceLocation& where() const { return where_; }
  // The message as the user sees it: a heading, the text and the location.
  std::string report() const;

 private:
  SourceLocation where_;
};

// Throw a FatalError (an I/O error when the location is known).
[[noreturn]] void fatalError(std::string message);
[[noreturn]] void fatalIOError(const SourceLocation& where, std::string message);

// A warning on stderr and in the log ("--> Warning: ..."), with the location if given.
void warning(const std::string& message, const SourceLocation& where = {});

// Number of warnings issued so far (tests and end-of-run summaries use it).
int warningCount();

}  // namespace isph
