// Looking at field files without reading their values: readFieldInfo and listFields.
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <system_error>

#include "core/Error.hpp"
#include "core/fields/FieldHeader.hpp"
#include "core/fields/FieldIO.hpp"
#include "core/fields/FieldTextScanner.hpp"
#include "core/io/ReadFile.hpp"

namespace isph {

namespace {

// Enough for any header and the list size that follows it.
constexpr std::size_t headerBytes = 64 * 1024;

// The number of values of a list written without a size, (v v v): read the values.
std::size_t countUnsized(const std::filesystem::path& file, const std::string& className) {
  if (className == "scalarField") return readField<scalar>(file).size();
  if (className == "labelField") return readField<label>(file).size();
  if (className == "vectorField") return readField<Vec3>(file).size();
  if (className == "symmTensorField") return readField<SymmTensor>(file).size();
  fatalError(
      fmt::format("cannot count the values of {}: its class {} is not a particle field class",
                  file.string(), className));
}

}  // namespace

FieldFileInfo readFieldInfo(const std::filesystem::path& file) {
  std::string text = readFileBytes(file, headerBytes);
  std::optional<FieldHeader> h;
  if (text.size() < headerBytes) {
    h = parseFieldHeader(text, file.string());  // the whole file
  } else {
    try {
      h = parseFieldHeader(text, file.string());
      if (h->dataOffset + 256 > text.size()) h.reset();  // the size might be cut off
    } catch (const FatalError&) {
      h.reset();  // the header runs past the first block
    }
  }
  if (!h) {
    text = readFileBytes(file);
    h = parseFieldHeader(text, file.string());
  }

  FieldFileInfo info;
  info.className = h->className;
  info.object = h->object;
  info.format = h->format;
  FieldTextScanner in(text, h->dataOffset, h->dataLine, h->file);
  in.setContext(fmt::format("{} {}", h->className, h->object));
  std::uint64_t n = 0;
  if (in.acceptWord("uniform")) {
    info.uniform = true;
  } else if (in.tryReadSize(n)) {
    info.size = static_cast<std::size_t>(n);
  } else if (in.peek() == '(') {
    info.size = countUnsized(file, h->className);
  } else {
    in.expected("the number of values N, then ( values ); or N{value}; or 'uniform' value");
  }
  return info;
}

std::vector<std::string> listFields(const std::filesystem::path& cloudDir) {
  std::vector<std::string> names;
  std::error_code ec;
  if (!std::filesystem::is_directory(cloudDir, ec)) return names;
  for (std::filesystem::directory_iterator it(cloudDir, ec), end; !ec && it != end;
       it.increment(ec)) {
    const std::string name = it->path().filename().string();
    std::error_code typeEc;
    if (name.empty() || name[0] == '.' || !it->is_regular_file(typeEc)) continue;
    if (startsWithFoamFile(readFileBytes(it->path(), 16 * 1024))) names.push_back(name);
  }
  if (ec)
    fatalError(fmt::format("cannot list the fields in {}: {}", cloudDir.string(), ec.message()));
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace isph
