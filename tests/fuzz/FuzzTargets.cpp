#include "FuzzTargets.hpp"

#include <fmt/format.h>

#include <optional>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/fields/FieldIO.hpp"
#include "particleGeneration/CsvPoints.hpp"

namespace isph::fuzz {

namespace {

template <class F>
void tolerate(F&& f) {
  try {
    f();
  } catch (const FatalError&) {
  }
}

// Every value read as the types the applications read.
void readEntries(const Dictionary& d) {
  for (const Entry& e : d.entries()) {
    if (e.isDict()) {
      readEntries(e.dict());
      continue;
    }
    const std::string& k = e.key();
    tolerate([&] { d.get<double>(k); });
    tolerate([&] { d.get<int>(k); });
    tolerate([&] { d.get<long>(k); });
    tolerate([&] { d.get<bool>(k); });
    tolerate([&] { d.get<std::string>(k); });
    tolerate([&] { d.get<Vec3>(k); });
    tolerate([&] { d.get<SymmTensor>(k); });
    tolerate([&] { d.get<std::vector<double>>(k); });
    tolerate([&] { d.get<std::vector<Vec3>>(k); });
    tolerate([&] { d.get<std::vector<std::string>>(k); });
    tolerate([&] { d.getDimensions(k); });
    tolerate([&] { d.getChoice(k, {"ascii", "binary"}); });
    tolerate([&] { d.subDict(k); });
  }
}

struct FieldChoice {
  int type = 0;  // scalar, label, vector, symmTensor
  std::optional<std::size_t> size;
};

FieldChoice choose(std::string_view& bytes) {
  FieldChoice c;
  if (bytes.empty()) return c;
  const auto b = static_cast<unsigned char>(bytes.front());
  bytes.remove_prefix(1);
  c.type = b % 4;
  if (b & 4) c.size = static_cast<std::size_t>(b >> 3);
  return c;
}

const char* className(int type) {
  static const char* names[] = {"scalarField", "labelField", "vectorField", "symmTensorField"};
  return names[type];
}

template <class T>
void parse(std::string_view text, const FieldChoice& c) {
  tolerate([&] {
    const std::vector<T> values = parseField<T>(text, "fuzz/field", c.size);
    if (c.size && values.size() != *c.size)
      std::abort();  // the size check let a wrong size through
  });
}

void parseAny(std::string_view text, const FieldChoice& c) {
  switch (c.type) {
    case 0:
      parse<scalar>(text, c);
      break;
    case 1:
      parse<label>(text, c);
      break;
    case 2:
      parse<Vec3>(text, c);
      break;
    default:
      parse<SymmTensor>(text, c);
      break;
  }
}

}  // namespace

void dictionary(std::string_view text) {
  tolerate([&] {
    const Dictionary d = Dictionary::parse(text, "fuzz/dict");
    readEntries(d);
    const std::string written = d.write();
    tolerate([&] { Dictionary::parse(written, "fuzz/written"); });
  });
}

void fieldFile(std::string_view bytes) {
  const FieldChoice c = choose(bytes);
  parseAny(bytes, c);
}

void binaryFieldData(std::string_view bytes) {
  const FieldChoice c = choose(bytes);
  std::string text = fmt::format(
      "FoamFile\n{{\n    version 2.0;\n    format binary;\n    arch \"LSB;label=32;scalar=64\";\n"
      "    class {};\n    object f;\n}}\n",
      className(c.type));
  text.append(bytes.data(), bytes.size());
  parseAny(text, c);
}

void csvPoints(std::string_view text) {
  tolerate([&] {
    const CsvPoints p = parseCsvPoints(text, "fuzz.csv");
    if (p.points.size() != p.lines.size()) std::abort();
  });
}

}  // namespace isph::fuzz
