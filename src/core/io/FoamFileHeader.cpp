// FoamFile header and footer text.
#include "core/io/FoamFileHeader.hpp"

#include <fmt/format.h>

#include "core/Types.hpp"
#include "core/Version.hpp"

namespace isph {

std::string foamFileArch() {
  return fmt::format("LSB;label={};scalar={}", 8 * sizeof(label), 8 * sizeof(scalar));
}

std::string foamFileHeader(std::string_view className, std::string_view object,
                           std::string_view location, bool binary) {
  std::string out;
  out.reserve(1024);
  // 79 columns, as OpenFOAM's banner.
  out += "/*--------------------------------*- C++ -*----------------------------------*\\\n";
  out += fmt::format("|{:<77}|\n", " isphLandslide: incompressible SPH for landslide runout");
  out += fmt::format("|{:<77}|\n", fmt::format(" Version: {}", gitVersion()));
  out +=
      "\\*---------------------------------------------------------------------------*/\n"
      "FoamFile\n"
      "{\n";
  auto entry = [&out](std::string_view key, std::string_view value) {
    out += fmt::format("    {:<12}{};\n", key, value);
  };
  entry("version", "2.0");
  entry("format", binary ? "binary" : "ascii");
  entry("arch", fmt::format("\"{}\"", foamFileArch()));
  entry("class", className);
  if (!location.empty()) entry("location", fmt::format("\"{}\"", location));
  entry("object", object);
  out +=
      "}\n"
      "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n"
      "\n";
  return out;
}

std::string foamFileFooter() {
  return "\n\n// ************************************************************************* //\n";
}

}  // namespace isph
