#pragma once
// Reading a whole file (or its first bytes) into memory in one go.
#include <cstddef>
#include <filesystem>
#include <string>

namespace isph {

// The bytes of `file`, at most `maxBytes` of them; a FatalError naming the file and the
// system's reason when it cannot be opened or read.
std::string readFileBytes(const std::filesystem::path& file,
                          std::size_t maxBytes = std::string::npos);

}  // namespace isph
