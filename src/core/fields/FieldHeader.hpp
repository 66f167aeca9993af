#pragma once
// The FoamFile header of a field file as field I/O uses it: class, object, format, where
// the data begins, and the check that binary data matches this build's arch.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "core/Error.hpp"
#include "core/fields/FieldIO.hpp"

namespace isph {

struct FieldHeader {
  std::shared_ptr<const std::string> file;
  std::string className;
  SourceLocation classLocation;
  std::string object;
  WriteFormat format = WriteFormat::ascii;
  std::size_t dataOffset = 0;  // byte offset just after the FoamFile dictionary
  int dataLine = 1;            // the line that offset is on
};

// Parse the FoamFile header at the start of `text` (comments before it allowed). A
// FatalError names the file and line when there is no header, it is malformed, its format
// is not ascii/binary, or a binary file's arch differs from this build's.
FieldHeader parseFieldHeader(std::string_view text, const std::string& fileName);

// True when the first thing in `text` after comments and white space is the word FoamFile.
bool startsWithFoamFile(std::string_view text);

}  // namespace isph
