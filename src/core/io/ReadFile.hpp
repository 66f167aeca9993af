#pragma once
// Reading a whole file (or its first bytes) into memory in one go. Only regular files are
// read: a device (/dev/zero never ends), a FIFO or a directory is refused with a FatalError.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace isph {

// The bytes of `file`, at most `maxBytes` of them; a FatalError naming the file and the
// system's reason when it cannot be opened or read, or is not a regular file.
std::string readFileBytes(const std::filesystem::path& file,
                          std::size_t maxBytes = std::string::npos);

// The whole of `file`, which must hold at most `limit` bytes: a larger one is a FatalError
// naming the file, its size and the limit for `what` it is read as ("a dictionary").
std::string readWholeFile(const std::filesystem::path& file, std::size_t limit,
                          std::string_view what);

// "256 MiB", "1.5 GiB", "300 bytes": a size for messages.
std::string bytesText(double bytes);

}  // namespace isph
