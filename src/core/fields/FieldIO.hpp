#pragma once
// Reading and writing particle fields, <time>/lagrangian/<cloud>/<field>, in OpenFOAM's
// lagrangian layout: a FoamFile header (class scalarField|vectorField|labelField|
// symmTensorField), then
//   ascii:  N ( one value per line )       vectors (x y z), symmTensors (xx xy xz yy yz zz)
//   binary: N (<N values as raw little-endian bytes>)
// Binary reads back exactly; ascii to `precision` significant digits (17 is exact).
// Reading also accepts N(v v v) on one line, an unsized (v v v), N{v} and `uniform v`.
// Errors name the file, the line and what was expected; a value that is not a finite number
// (nan, inf, 1e400; ascii or binary) is one.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/Types.hpp"

namespace isph {

enum class WriteFormat { ascii, binary };

struct FieldWriteOptions {
  WriteFormat format = WriteFormat::ascii;
  int precision = 6;  // significant digits of ascii output (printf's %.*g); at least 1
  // The header's location, e.g. "0.1/lagrangian/particles" (left out when empty).
  std::string location;
};

// T is one of scalar (double), label (int32), Vec3, SymmTensor (Types.hpp). The header's object
// is the file name. Written atomically (writeFileAtomic); the folder must exist.
template <class T>
void writeField(const std::filesystem::path& file, const std::vector<T>& values,
                const FieldWriteOptions& options);

// Reads ascii or binary (from the header's `format`), `N(...)` lists, and uniform forms `N{value}`;
// `uniform <value>` is accepted when expectedSize is given. Checks the header class against T and
// the size against expectedSize, and in binary the header's arch (byte order, label and scalar
// sizes). Errors name the file and the line.
template <class T>
std::vector<T> readField(const std::filesystem::path& file,
                         std::optional<std::size_t> expectedSize = {});

// readField of the text of a field file already in memory; `fileName` is what errors name.
template <class T>
std::vector<T> parseField(std::string_view text, const std::string& fileName,
                          std::optional<std::size_t> expectedSize = {});

// The line of value `index` (0-based) of an ascii field file, for messages about that value;
// 0 for a binary or uniform field, or one that cannot be read.
template <class T>
int fieldValueLine(const std::filesystem::path& file, std::size_t index);

// "scalarField", "labelField", "vectorField", "symmTensorField".
template <class T>
std::string fieldClassName();

struct FieldFileInfo {
  std::string className;
  std::string object;  // the header's object (the file name when the header has none)
  WriteFormat format = WriteFormat::ascii;
  std::size_t size = 0;  // number of values; 0 for a `uniform` field (which has no size)
  bool uniform = false;  // written as `uniform <value>`
};

// Header + size only (cheap: reads the start of the file unless the list has no size prefix).
FieldFileInfo readFieldInfo(const std::filesystem::path& file);

// Sorted names of the files in `cloudDir` that start with a FoamFile header (hidden files
// skipped); empty when the folder does not exist.
std::vector<std::string> listFields(const std::filesystem::path& cloudDir);

}  // namespace isph
