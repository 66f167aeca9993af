// Writing and reading particle fields in OpenFOAM's lagrangian ascii and binary layouts.
#include "core/fields/FieldIO.hpp"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <type_traits>

#include "core/Error.hpp"
#include "core/fields/FieldHeader.hpp"
#include "core/fields/FieldTextScanner.hpp"
#include "core/fields/FieldTraits.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/FoamFileHeader.hpp"
#include "core/io/ReadFile.hpp"

namespace isph {

static_assert(
    std::endian::native == std::endian::little,
    "binary field files are little-endian (arch LSB); this build would need byte swapping");

namespace {

// A uniform list N{value} is a few bytes of text for N values in memory. Where the caller knows
// the particle count (every field but the positions, which set it) N must equal it; elsewhere N
// is limited as the dictionary's lists are (DictionaryLimits::maxListElements): the fuzzer's
// 16-byte "999999943{0}" asked for 4 GB. A list N( ... ) is bounded by the file's own size.
constexpr std::size_t maxUniformWithoutCount = std::size_t{1} << 24;

// ---- writing ---------------------------------------------------------------------------

// printf's %.{precision}g (std::to_chars: about twice as fast as fmt's precision path).
void appendScalar(std::string& out, double v, int precision) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, precision);
  if (r.ec == std::errc{}) {
    out.append(buf, r.ptr);
  } else {
    fmt::format_to(std::back_inserter(out), "{:.{}g}", v, precision);  // a silly precision
  }
}

template <class T>
void appendAscii(std::string& out, const T& v, int precision) {
  if constexpr (std::is_same_v<T, label>) {
    char buf[16];
    const auto end = fmt::format_to(buf, "{}", v);
    out.append(buf, end);
  } else if constexpr (std::is_same_v<T, scalar>) {
    appendScalar(out, v, precision);
  } else {
    out += '(';
    for (int k = 0; k < FieldTraits<T>::nComponents; ++k) {
      if (k) out += ' ';
      appendScalar(out, v[k], precision);
    }
    out += ')';
  }
}

template <class T>
std::string formatField(const std::vector<T>& values, const std::string& object,
                        const FieldWriteOptions& options) {
  const bool binary = options.format == WriteFormat::binary;
  std::string out = foamFileHeader(FieldTraits<T>::className, object, options.location, binary);
  const std::size_t n = values.size();
  if (binary) {
    static_assert(isPackedField<T>);
    out += fmt::format("\n{}\n", n);
    if (n > 0) {
      const std::size_t bytes = n * sizeof(T);
      out.reserve(out.size() + bytes + 128);
      out += '(';
      out.append(static_cast<const char*>(static_cast<const void*>(values.data())), bytes);
      out += ")\n";
    }
  } else if (n == 0) {
    out += "\n0()\n";
  } else {
    out += fmt::format("\n{}\n(\n", n);
    out.reserve(out.size() + n * FieldTraits<T>::nComponents * (options.precision + 8) + 128);
    for (const T& v : values) {
      appendAscii(out, v, options.precision);
      out += '\n';
    }
    out += ")\n";
  }
  out += foamFileFooter();
  return out;
}

// ---- reading ---------------------------------------------------------------------------

template <class T>
T readValue(FieldTextScanner& in) {
  using Traits = FieldTraits<T>;
  if constexpr (std::is_same_v<T, label>) {
    return in.readLabel(Traits::expected);
  } else if constexpr (std::is_same_v<T, scalar>) {
    return in.readScalar(Traits::expected);
  } else {
    T v;
    if (!in.accept('(')) in.expected(Traits::expected);
    for (int k = 0; k < Traits::nComponents; ++k) v[k] = in.readScalar(Traits::expected);
    if (!in.accept(')')) in.expected(Traits::expected);
    return v;
  }
}

// Binary data holds whatever bits were written: nan and inf are refused as the ascii reader
// refuses them, naming the value and its byte offset (`in` is at the start of the data).
template <class T>
void checkFinite(const FieldTextScanner& in, const std::vector<T>& values) {
  if constexpr (!std::is_same_v<T, label>) {
    constexpr int nc = FieldTraits<T>::nComponents;
    const auto* c = static_cast<const scalar*>(static_cast<const void*>(values.data()));
    const std::size_t total = values.size() * nc;
    for (std::size_t k = 0; k < total; ++k) {
      if (std::isfinite(c[k])) continue;
      in.error(fmt::format("value {} of {} (component {} at byte {} of the file) is not a finite number ({}) in "
                           "the binary data",
                           k / nc + 1, values.size(), k % nc + 1, in.offset() + k * sizeof(scalar), c[k]));
    }
  }
}

template <class T>
std::vector<T> readBinaryList(FieldTextScanner& in, std::size_t n) {
  // `(` is followed directly by the raw bytes, and they by `)`.
  const std::size_t bytes = n * sizeof(T);
  if (n > in.remaining() / sizeof(T) || in.remaining() < bytes + 1) {
    in.error(fmt::format(
        "the file is truncated: the binary list of {} values needs {} bytes of data and a "
        "closing ')' but the file ends {} bytes after the '('",
        n, bytes, in.remaining()));
  }
  std::vector<T> values(n);
  if (n > 0) std::memcpy(static_cast<void*>(values.data()), in.text().data() + in.offset(), bytes);
  checkFinite(in, values);
  in.skipBytes(bytes);
  if (in.peek() != ')') {
    in.error(fmt::format(
        "expected ')' after the {} bytes of binary data of {} values, found {}: the file is "
        "corrupt or its size is wrong",
        bytes, n, in.describeNext()));
  }
  in.skipBytes(1);
  return values;
}

template <class T>
std::vector<T> readAsciiList(FieldTextScanner& in, std::size_t n) {
  if (n > in.remaining()) {
    in.error(fmt::format(
        "the list says it holds {} values but the file ends {} bytes later (truncated?)", n,
        in.remaining()));
  }
  std::vector<T> values(n);
  for (std::size_t i = 0; i < n; ++i) {
    in.setElement(i, n);
    in.skipSpace();
    if (in.peek() == ')') {
      in.error(fmt::format("the list ends after {} values but its size says {}", i, n));
    }
    values[i] = readValue<T>(in);
  }
  in.setElement(0, 0);
  if (!in.accept(')')) {
    in.expected(fmt::format(
        "')' closing the list of {} values (the list holds more values than its size?)", n));
  }
  return values;
}

template <class T>
std::vector<T> readUnsizedAsciiList(FieldTextScanner& in) {
  std::vector<T> values;
  in.expect('(', "'('");
  for (;;) {
    in.setElement(values.size(), FieldTextScanner::unknownCount);
    in.skipSpace();
    if (in.atEnd())
      in.expected(fmt::format("{} or ')' closing the list", FieldTraits<T>::expected));
    if (in.peek() == ')') break;
    values.push_back(readValue<T>(in));
  }
  in.setElement(0, 0);
  in.expect(')', "')'");
  return values;
}

template <class T>
std::vector<T> readData(FieldTextScanner& in, WriteFormat format,
                        std::optional<std::size_t> expectedSize) {
  in.skipSpace();
  const SourceLocation start = in.here();
  auto checkSize = [&](std::size_t n) {
    if (expectedSize && n != *expectedSize) {
      fatalIOError(
          start,
          fmt::format("{}: the field holds {} values but {} were expected (one per particle)",
                      in.context(), n, *expectedSize));
    }
  };

  if (in.acceptWord("uniform")) {
    if (!expectedSize) {
      in.error(
          "a 'uniform' field has no size: it can only be read where the number of particles is "
          "known");
    }
    const T v = readValue<T>(in);
    return std::vector<T>(*expectedSize, v);
  }
  std::uint64_t n64 = 0;
  if (!in.tryReadSize(n64)) {
    if (format == WriteFormat::ascii && in.peek() == '(') {
      std::vector<T> values = readUnsizedAsciiList<T>(in);
      checkSize(values.size());
      return values;
    }
    in.expected("the number of values N, then ( values ); or N{value}; or 'uniform' value");
  }
  if (n64 > static_cast<std::uint64_t>(std::numeric_limits<label>::max())) {
    fatalIOError(start, fmt::format("{}: the list size {} is beyond the largest particle count {}",
                                    in.context(), n64, std::numeric_limits<label>::max()));
  }
  const auto n = static_cast<std::size_t>(n64);
  checkSize(n);
  if (in.accept('{')) {  // N{value}: N copies of one value
    if (!expectedSize && n > maxUniformWithoutCount) {
      fatalIOError(start, fmt::format("{}: a uniform list N{{value}} of {} values ({} for a few bytes of "
                                      "text) where the particle count is not yet known is refused above "
                                      "{} values; write the values as a list N( ... )",
                                      in.context(), n, bytesText(static_cast<double>(n) * sizeof(T)),
                                      maxUniformWithoutCount));
    }
    const T v = readValue<T>(in);
    in.expect('}', "'}' closing the uniform list N{value}");
    return std::vector<T>(n, v);
  }
  if (format == WriteFormat::binary) {
    in.skipSpace();
    if (n == 0 && in.peek() != '(') return {};  // OpenFOAM writes an empty binary list as just "0"
    if (!in.accept('(')) in.expected(fmt::format("'(' opening the binary list of {} values", n));
    return readBinaryList<T>(in, n);
  }
  if (!in.accept('(')) in.expected(fmt::format("'(' opening the list of {} values", n));
  return readAsciiList<T>(in, n);
}

}  // namespace

// ---- public API ----------------------------------------------------------------------------

template <class T>
std::string fieldClassName() {
  return FieldTraits<T>::className;
}

template <class T>
void writeField(const std::filesystem::path& file, const std::vector<T>& values,
                const FieldWriteOptions& options) {
  if (options.precision < 1) {
    fatalError(fmt::format("cannot write {}: writePrecision must be at least 1, not {}",
                           file.string(), options.precision));
  }
  writeFileAtomic(file, formatField(values, file.filename().string(), options));
}

template <class T>
std::vector<T> readField(const std::filesystem::path& file,
                         std::optional<std::size_t> expectedSize) {
  return parseField<T>(readFileBytes(file), file.string(), expectedSize);
}

template <class T>
std::vector<T> parseField(std::string_view text, const std::string& fileName,
                          std::optional<std::size_t> expectedSize) {
  const FieldHeader h = parseFieldHeader(text, fileName);
  if (h.className != FieldTraits<T>::className) {
    fatalIOError(h.classLocation, fmt::format("field '{}' is a {} but a {} was expected here",
                                              h.object, h.className, FieldTraits<T>::className));
  }
  FieldTextScanner in(text, h.dataOffset, h.dataLine, h.file);
  in.setContext(fmt::format("{} {}", h.className, h.object));
  std::vector<T> values = readData<T>(in, h.format, expectedSize);
  in.skipSpace();
  if (!in.atEnd())
    in.error(fmt::format("unexpected {} after the end of the field's list", in.describeNext()));
  return values;
}

template <class T>
int fieldValueLine(const std::filesystem::path& file, std::size_t index) {
  try {
    const std::string text = readFileBytes(file);
    const FieldHeader h = parseFieldHeader(text, file.string());
    if (h.format == WriteFormat::binary) return 0;
    FieldTextScanner in(text, h.dataOffset, h.dataLine, h.file);
    std::uint64_t n = 0;
    in.tryReadSize(n);
    if (!in.accept('(')) return 0;
    for (std::size_t i = 0; i < index; ++i) readValue<T>(in);
    in.skipSpace();
    return in.atEnd() ? 0 : in.here().line;
  } catch (const FatalError&) {
    return 0;
  }
}

#define ISPH_INSTANTIATE_FIELD_IO(T)                                               \
  template std::string fieldClassName<T>();                                        \
  template void writeField<T>(const std::filesystem::path&, const std::vector<T>&, \
                              const FieldWriteOptions&);                           \
  template std::vector<T> readField<T>(const std::filesystem::path&, std::optional<std::size_t>); \
  template std::vector<T> parseField<T>(std::string_view, const std::string&, std::optional<std::size_t>); \
  template int fieldValueLine<T>(const std::filesystem::path&, std::size_t);

ISPH_INSTANTIATE_FIELD_IO(scalar)
ISPH_INSTANTIATE_FIELD_IO(label)
ISPH_INSTANTIATE_FIELD_IO(Vec3)
ISPH_INSTANTIATE_FIELD_IO(SymmTensor)

#undef ISPH_INSTANTIATE_FIELD_IO

}  // namespace isph
