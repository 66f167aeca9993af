#pragma once
// The FoamFile header that opens every field file (a short banner comment, the FoamFile
// dictionary and a separator line) and the closing line, in OpenFOAM's layout so that
// OpenFOAM tools and ParaView readers accept the files.
#include <string>
#include <string_view>

namespace isph {

// The architecture this build writes binary data in ("LSB;label=32;scalar=64").
std::string foamFileArch();

// Banner comment + `FoamFile { version 2.0; format ascii|binary; arch "..."; class <className>;
// location "<location>"; object <object>; }` + the `// * * * ... //` separator and a blank line.
// An empty `location` is left out.
std::string foamFileHeader(std::string_view className, std::string_view object,
                           std::string_view location, bool binary);

// "\n\n// ****...**** //\n": the line that closes a field file.
std::string foamFileFooter();

}  // namespace isph
