// Parsing and checking the FoamFile header of a field file.
#include "core/fields/FieldHeader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

#include "core/dictionary/Dictionary.hpp"
#include "core/fields/FieldTextScanner.hpp"
#include "core/io/FoamFileHeader.hpp"

namespace isph {

namespace {

// Refuse binary data whose byte order or label/scalar sizes differ from ours. Missing parts
// of arch (or a missing arch) are taken to be ours, as OpenFOAM does.
void checkArch(const Dictionary& header, const std::string& fileName) {
  const Entry* e = header.findEntry("arch");
  if (!e) return;
  const std::string arch = header.get<std::string>("arch");
  bool mismatch = false;
  std::string_view rest = arch;
  while (!rest.empty()) {
    const auto semi = rest.find(';');
    const std::string_view part = rest.substr(0, semi);
    rest = semi == std::string_view::npos ? std::string_view{} : rest.substr(semi + 1);
    if (part == "MSB") mismatch = true;
    for (const auto& [key, bits] :
         {std::pair<std::string_view, int>{"label=", 8 * sizeof(label)},
          std::pair<std::string_view, int>{"scalar=", 8 * sizeof(scalar)}}) {
      if (part.substr(0, key.size()) != key) continue;
      int value = 0;
      const auto digits = part.substr(key.size());
      const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
      if (ec != std::errc{} || ptr != digits.data() + digits.size() || value != bits)
        mismatch = true;
    }
  }
  if (mismatch) {
    fatalIOError(
        e->location(),
        fmt::format(
            "{}: the binary data was written with arch \"{}\" but this build reads and writes "
            "\"{}\"; convert the file to ascii with the program that wrote it",
            fileName, arch, foamFileArch()));
  }
}

}  // namespace

bool startsWithFoamFile(std::string_view text) {
  try {
    FieldTextScanner in(text, 0, 1, nullptr);
    return in.acceptWord("FoamFile");
  } catch (const FatalError&) {
    return false;  // an unclosed comment: not a field file we could read
  }
}

FieldHeader parseFieldHeader(std::string_view text, const std::string& fileName) {
  FieldHeader h;
  h.file = std::make_shared<const std::string>(fileName);
  {
    FieldTextScanner in(text, 0, 1, h.file);
    if (!in.acceptWord("FoamFile")) {
      in.skipSpace();
      in.expected(
          "a FoamFile header (FoamFile { version 2.0; format ascii; class ...; object ...; })");
    }
  }
  std::size_t end = 0;
  const Dictionary top = Dictionary::parseHeader(text, fileName, end);
  const Dictionary& header = top.subDict("FoamFile");

  h.className = header.get<std::string>("class");
  h.classLocation = header.entry("class").location();
  h.object = header.getOptional<std::string>("object").value_or(
      std::filesystem::path(fileName).filename().string());
  if (header.found("format")) {
    h.format = header.getChoice("format", {"ascii", "binary"}) == "binary" ? WriteFormat::binary
                                                                           : WriteFormat::ascii;
  }
  if (h.format == WriteFormat::binary) checkArch(header, fileName);

  h.dataOffset = end;
  h.dataLine = 1 + static_cast<int>(std::count(
                       text.begin(), text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
  return h;
}

}  // namespace isph
