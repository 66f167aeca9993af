#pragma once
// The table a function object writes a row to after each step it is due
// (postProcessing/<name>/<startTime>/force.dat), written so that a full disk or a crash loses no
// more than the row being written and never leaves a part of one:
//  - the first write (the header and the first row) replaces the file atomically (AtomicFile.hpp):
//    a run that fails there leaves the previous file (an earlier attempt's rows) as it was;
//  - each later row is appended whole: a write that fails part-way is cut back to the last whole
//    row, and the FatalError gives the reason ("No space left on device");
//  - dropHalfRows, at the start of a run, ends every table of the function object at its last
//    whole row: a kill -9 in the middle of a write leaves a row without its newline. It says so in
//    the log.
#include <filesystem>
#include <string>

namespace isph {

class RowFile {
 public:
  // `owner`: "function object 'barrierForce'", for messages.
  RowFile(std::filesystem::path file, std::string owner);
  ~RowFile();
  RowFile(const RowFile&) = delete;
  RowFile& operator=(const RowFile&) = delete;

  bool started() const { return fd_ >= 0; }
  // Whole lines (each ending in '\n'): the first call writes them as the file's new content, the
  // later ones append them. FatalError naming the file and the reason when they cannot be written.
  void write(const std::string& lines);

  const std::filesystem::path& path() const { return file_; }

 private:
  std::filesystem::path file_;
  std::string owner_;
  int fd_ = -1;
};

// Every postProcessing/<name>/<time>/<file> of `dir` (postProcessing/<name>) that ends without a
// newline is cut back to its last whole line, with a log line naming it and the bytes dropped.
void dropHalfRows(const std::filesystem::path& dir, const std::string& fileName);

}  // namespace isph
