#pragma once
// The bodies of the libFuzzer targets (tests/fuzz/README.md): each feeds bytes to a reader as a
// case file would, and uses what it read the way applications do. A FatalError is the right
// answer to bad input; anything else (a crash, a sanitizer report, another exception, a hang)
// is a finding. Compiled into the fuzzers (clang, -fsanitize=fuzzer,address,undefined) and
// into FuzzRegressionTest, which replays the inputs kept under tests/fuzz/regressions/.
#include <string_view>

namespace isph::fuzz {

// OpenFOAM dictionary text: parsed, every entry read as the types cases read, written and
// parsed again.
void dictionary(std::string_view text);
// A whole field file (header and data; ascii or binary as its header says). The first byte
// picks the field type and whether a size is expected; the rest is the file.
void fieldFile(std::string_view bytes);
// The data section of a binary field after a fixed binary header; the first byte as above.
void binaryFieldData(std::string_view bytes);
// A CSV file of points.
void csvPoints(std::string_view text);

}  // namespace isph::fuzz
