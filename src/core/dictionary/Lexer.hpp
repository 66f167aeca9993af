#pragma once
// Splits OpenFOAM dictionary text into tokens, skipping // and /* */ comments and
// keeping the line and column of every token for error messages.
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/dictionary/Token.hpp"

namespace isph {

class Lexer {
 public:
  // `text` must outlive the lexer; `fileName` is what error messages show.
  Lexer(std::string_view text, std::shared_ptr<const std::string> fileName);

  // The next token, or nullopt at the end of the text.
  std::optional<Token> next();
  std::optional<Token> peek();

  // Byte offset just past the last token returned by next().
  std::size_t offset() const { return offset_; }
  // The location of the current read position (for "unexpected end of file" errors).
  SourceLocation here() const;

 private:
  void skipSpaceAndComments();
  char at(std::size_t i) const { return i < text_.size() ? text_[i] : '\0'; }
  void advance(std::size_t n = 1);
  Token make(TokenKind kind, std::string text, int line, int column) const;
  Token lexString(int line, int column);
  Token lexVariable(int line, int column);
  Token lexWordOrNumber(int line, int column);
  std::string readRun();
  // FatalError at the token's start when it grows beyond DictionaryLimits::maxTokenBytes.
  void checkLength(std::size_t length, int line, int column) const;

  std::string_view text_;
  std::shared_ptr<const std::string> file_;
  std::size_t pos_ = 0;
  std::size_t offset_ = 0;
  int line_ = 1;
  int column_ = 1;
  std::optional<Token> peeked_;
  std::size_t peekedOffset_ = 0;
};

// True when the whole of `s` is a finite number; sets value and whether it is an integer. A
// number too small for a double (1e-400) reads as the nearest one (0), as strtod does.
bool parseNumber(std::string_view s, double& value, bool& isInteger);

// True when `s` is spelled as a number that is not finite: nan, inf, infinity (any case,
// signed) or one too large for a double (1e400). Readers of numbers say "not a finite number".
bool isNonFiniteNumber(std::string_view s);

}  // namespace isph
