#pragma once
// A fast cursor over the text of a field file's data section: skips white space and
// comments, counts lines, reads numbers with std::from_chars (no iostreams), and reports
// errors at the file, line and column it has reached, saying what was expected.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "core/Error.hpp"
#include "core/Types.hpp"

namespace isph {

class FieldTextScanner {
 public:
  // Scan `text` from byte `pos`, which is on line `line` (1-based). `text` must outlive this.
  FieldTextScanner(std::string_view text, std::size_t pos, int line,
                   std::shared_ptr<const std::string> file);

  // Skip white space and // or /* */ comments.
  void skipSpace() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        lineStart_ = ++pos_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++pos_;
      } else if (c == '/' && pos_ + 1 < text_.size() &&
                 (text_[pos_ + 1] == '/' || text_[pos_ + 1] == '*')) {
        skipComment();
      } else {
        return;
      }
    }
  }

  bool atEnd() const { return pos_ >= text_.size(); }
  char peek() const { return atEnd() ? '\0' : text_[pos_]; }
  std::size_t offset() const { return pos_; }
  std::size_t remaining() const { return text_.size() - pos_; }
  std::string_view text() const { return text_; }
  // Jump over `n` bytes of binary data (line counting stops being meaningful there).
  void skipBytes(std::size_t n) { pos_ += n; }

  // After skipSpace: consume `c` if it is next.
  bool accept(char c) {
    skipSpace();
    if (peek() != c) return false;
    ++pos_;
    return true;
  }
  void expect(char c, std::string_view what) {
    if (!accept(c)) expected(what);
  }
  // A whole word (followed by a delimiter).
  bool acceptWord(std::string_view word);

  // A finite number: nan, inf and numbers beyond a double's range (1e400) are errors ("not a
  // finite number"); one too small for a double (1e-400) reads as the nearest one, as strtod.
  double readScalar(std::string_view what) {
    skipSpace();
    std::size_t p = pos_;
    if (p < text_.size() && text_[p] == '+') ++p;
    double v = 0;
    const auto [ptr, ec] = std::from_chars(text_.data() + p, text_.data() + text_.size(), v);
    if (ec != std::errc{} || !delimiterAt(ptr)) {
      if (ec == std::errc::result_out_of_range && delimiterAt(ptr)) {
        v = outOfRangeScalar(p, ptr, what);
      } else {
        expected(what);
      }
    }
    if (!std::isfinite(v)) notFinite(what);
    pos_ = static_cast<std::size_t>(ptr - text_.data());
    return v;
  }

  label readLabel(std::string_view what) {
    skipSpace();
    std::size_t p = pos_;
    if (p < text_.size() && text_[p] == '+') ++p;
    label v = 0;
    const auto [ptr, ec] = std::from_chars(text_.data() + p, text_.data() + text_.size(), v);
    if (ec != std::errc{} || !delimiterAt(ptr)) {
      if (ec == std::errc::result_out_of_range && delimiterAt(ptr)) outOfRange(what);
      expected(what);
    }
    pos_ = static_cast<std::size_t>(ptr - text_.data());
    return v;
  }

  // A list size: a non-negative integer (which may be followed directly by '(' or '{').
  bool tryReadSize(std::uint64_t& size);

  SourceLocation here() const;
  // Error at the current position: "expected <what>, found <next token>".
  [[noreturn]] void expected(std::string_view what) const;
  [[noreturn]] void error(std::string message) const;
  // The next token for messages: "'abc'", "'('" or "the end of the file".
  std::string describeNext() const;

  // Context for messages: "vectorField U, value 4 of 5: expected ...". `index` is 0-based;
  // `count` is unknownCount for a list without a size, 0 outside a list.
  static constexpr std::size_t unknownCount = static_cast<std::size_t>(-1);
  void setContext(std::string context) { context_ = std::move(context); }
  const std::string& context() const { return context_; }
  void setElement(std::size_t index, std::size_t count) {
    element_ = index;
    count_ = count;
  }

 private:
  void skipComment();
  [[noreturn]] void outOfRange(std::string_view what) const;
  [[noreturn]] void notFinite(std::string_view what) const;
  // The value of the number text_[first, last) that from_chars found out of range: the
  // nearest double when it is too small, else the "not a finite number" error.
  double outOfRangeScalar(std::size_t first, const char* last, std::string_view what) const;
  bool delimiterAt(const char* p) const {
    if (p == text_.data() + text_.size()) return true;
    const char c = *p;
    return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '(' || c == ')' || c == '{' ||
           c == '}' || c == ';' || c == '\f' || c == '\v' ||
           (c == '/' && p + 1 < text_.data() + text_.size() && (p[1] == '/' || p[1] == '*'));
  }

  std::string_view text_;
  std::size_t pos_;
  std::size_t lineStart_;
  int line_;
  std::shared_ptr<const std::string> file_;
  std::string context_;
  std::size_t element_ = 0;
  std::size_t count_ = 0;  // 0: not inside a list
};

}  // namespace isph
