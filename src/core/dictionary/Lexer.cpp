#include "core/dictionary/Lexer.hpp"

#include "core/dictionary/DictionaryLimits.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace isph {

namespace {

bool isPunctChar(char c) {
  return c == ';' || c == '{' || c == '}' || c == '(' || c == ')' || c == '[' || c == ']';
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

// Characters that end a word: white space, punctuation, quotes.
bool endsWord(char c) { return c == '\0' || isSpace(c) || isPunctChar(c) || c == '"'; }

}  // namespace

std::string Token::describe() const {
  switch (kind) {
    case TokenKind::Word: return fmt::format("word '{}'", text);
    case TokenKind::String: return fmt::format("string \"{}\"", text);
    case TokenKind::Number: return fmt::format("number {}", text);
    case TokenKind::Punct: return fmt::format("'{}'", text);
    case TokenKind::Variable: return fmt::format("variable '${}'", text);
    case TokenKind::Directive: return fmt::format("directive '#{}'", text);
  }
  return text;
}

std::string Token::spelling() const {
  switch (kind) {
    case TokenKind::String: {
      std::string out = "\"";
      for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
      }
      return out + '"';
    }
    case TokenKind::Variable: return "$" + text;
    case TokenKind::Directive: return "#" + text;
    default: return text;
  }
}

namespace {

// The value of a number spelled `body` (no leading '+') whose magnitude is beyond a double's
// range: ±inf when too large, the nearest double (0 or subnormal) when too small.
double outOfRangeValue(std::string_view body) {
  const std::string copy(body);
  errno = 0;
  return std::strtod(copy.c_str(), nullptr);
}

}  // namespace

bool parseNumber(std::string_view s, double& value, bool& isInteger) {
  if (s.empty()) return false;
  std::string_view body = s;
  if (body.front() == '+') body.remove_prefix(1);  // from_chars rejects a leading '+'
  if (body.empty()) return false;
  const char c0 = body.front();
  if (!(std::isdigit(static_cast<unsigned char>(c0)) || c0 == '-' || c0 == '.')) return false;
  const char* first = body.data();
  const char* last = body.data() + body.size();
  double v = 0;
  const auto result = std::from_chars(first, last, v);
  if (result.ptr != last) return false;
  if (result.ec == std::errc::result_out_of_range) {
    v = outOfRangeValue(body);
  } else if (result.ec != std::errc{}) {
    return false;
  }
  if (!std::isfinite(v)) return false;
  value = v;
  isInteger = body.find_first_of(".eE") == std::string_view::npos;
  return true;
}

bool isNonFiniteNumber(std::string_view s) {
  std::string_view body = s;
  if (!body.empty() && (body.front() == '+' || body.front() == '-')) body.remove_prefix(1);
  std::string lower(body);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (lower == "nan" || lower == "inf" || lower == "infinity") return true;
  if (lower.empty() || !(std::isdigit(static_cast<unsigned char>(lower[0])) || lower[0] == '.')) return false;
  double v = 0;
  const auto result = std::from_chars(lower.data(), lower.data() + lower.size(), v);
  return result.ptr == lower.data() + lower.size() && result.ec == std::errc::result_out_of_range &&
         !std::isfinite(outOfRangeValue(lower));
}

Lexer::Lexer(std::string_view text, std::shared_ptr<const std::string> fileName)
    : text_(text), file_(std::move(fileName)) {}

SourceLocation Lexer::here() const { return SourceLocation{file_, line_, column_}; }

void Lexer::advance(std::size_t n) {
  for (std::size_t k = 0; k < n && pos_ < text_.size(); ++k) {
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }
}

void Lexer::skipSpaceAndComments() {
  for (;;) {
    while (pos_ < text_.size() && isSpace(text_[pos_])) advance();
    if (at(pos_) == '/' && at(pos_ + 1) == '/') {
      while (pos_ < text_.size() && text_[pos_] != '\n') advance();
    } else if (at(pos_) == '/' && at(pos_ + 1) == '*') {
      const SourceLocation start = here();
      advance(2);
      while (pos_ < text_.size() && !(text_[pos_] == '*' && at(pos_ + 1) == '/')) advance();
      if (pos_ >= text_.size()) fatalIOError(start, "unterminated comment: '/*' without a closing '*/'");
      advance(2);
    } else {
      return;
    }
  }
}

Token Lexer::make(TokenKind kind, std::string text, int line, int column) const {
  Token t;
  t.kind = kind;
  t.text = std::move(text);
  t.loc = SourceLocation{file_, line, column};
  return t;
}

void Lexer::checkLength(std::size_t length, int line, int column) const {
  if (length <= DictionaryLimits::maxTokenBytes) return;
  fatalIOError(SourceLocation{file_, line, column},
               fmt::format("a word or string longer than {} KiB: no dictionary entry needs one (a missing "
                           "closing '\"'?)",
                           DictionaryLimits::maxTokenBytes >> 10));
}

std::string Lexer::readRun() {
  const int line = line_, column = column_;
  const std::size_t start = pos_;
  while (!endsWord(at(pos_)) && !(at(pos_) == '/' && (at(pos_ + 1) == '/' || at(pos_ + 1) == '*'))) {
    advance();
    checkLength(pos_ - start, line, column);
  }
  return std::string(text_.substr(start, pos_ - start));
}

Token Lexer::lexString(int line, int column) {
  const SourceLocation start = here();
  advance();  // opening quote
  std::string value;
  for (;;) {
    if (pos_ >= text_.size()) fatalIOError(start, "unterminated string: '\"' without a closing '\"'");
    const char c = text_[pos_];
    if (c == '"') {
      advance();
      break;
    }
    if (c == '\\' && (at(pos_ + 1) == '"' || at(pos_ + 1) == '\\')) {
      value += at(pos_ + 1);
      advance(2);
      continue;
    }
    value += c;
    advance();
    checkLength(value.size(), line, column);
  }
  return make(TokenKind::String, std::move(value), line, column);
}

Token Lexer::lexVariable(int line, int column) {
  advance();  // '$'
  std::string name;
  if (at(pos_) == '{') {
    const SourceLocation start = here();
    advance();
    while (pos_ < text_.size() && text_[pos_] != '}') {
      name += text_[pos_];
      advance();
      checkLength(name.size(), line, column);
    }
    if (pos_ >= text_.size()) fatalIOError(start, "unterminated '${': missing '}'");
    advance();
  } else {
    name = readRun();
  }
  if (name.empty()) fatalIOError(SourceLocation{file_, line, column}, "'$' must be followed by a keyword name");
  return make(TokenKind::Variable, std::move(name), line, column);
}

Token Lexer::lexWordOrNumber(int line, int column) {
  std::string run = readRun();
  if (run.empty()) {  // a NUL byte, which ends a word without being one: no progress otherwise
    fatalIOError(SourceLocation{file_, line, column},
                 "a NUL byte: a dictionary is text (a binary file, or one damaged on disk?)");
  }
  double value = 0;
  bool integer = false;
  if (parseNumber(run, value, integer)) {
    Token t = make(TokenKind::Number, std::move(run), line, column);
    t.number = value;
    t.isInteger = integer;
    return t;
  }
  return make(TokenKind::Word, std::move(run), line, column);
}

std::optional<Token> Lexer::peek() {
  if (!peeked_) {
    const std::size_t saved = offset_;
    peeked_ = next();
    peekedOffset_ = offset_;
    offset_ = saved;
  }
  return peeked_;
}

std::optional<Token> Lexer::next() {
  if (peeked_) {
    std::optional<Token> t = std::move(peeked_);
    peeked_.reset();
    offset_ = peekedOffset_;
    return t;
  }
  skipSpaceAndComments();
  if (pos_ >= text_.size()) {
    offset_ = pos_;
    return std::nullopt;
  }
  const int line = line_;
  const int column = column_;
  const char c = text_[pos_];
  Token t;
  if (isPunctChar(c)) {
    advance();
    t = make(TokenKind::Punct, std::string(1, c), line, column);
  } else if (c == '"') {
    t = lexString(line, column);
  } else if (c == '$') {
    t = lexVariable(line, column);
  } else if (c == '#' && std::isalpha(static_cast<unsigned char>(at(pos_ + 1)))) {
    advance();
    t = make(TokenKind::Directive, readRun(), line, column);
  } else {
    t = lexWordOrNumber(line, column);
  }
  offset_ = pos_;
  return t;
}

}  // namespace isph
