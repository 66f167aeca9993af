#include "core/dictionary/TokenReader.hpp"

#include <fmt/format.h>

#include "core/dictionary/Lexer.hpp"

namespace isph {

TokenReader::TokenReader(const std::vector<Token>& tokens, std::string context,
                         SourceLocation entryLocation)
    : tokens_(tokens), context_(std::move(context)), entryLocation_(std::move(entryLocation)) {}

SourceLocation TokenReader::location() const {
  if (i_ < tokens_.size()) return tokens_[i_].loc;
  if (!tokens_.empty()) return tokens_.back().loc;
  return entryLocation_;
}

const Token& TokenReader::peek() const {
  if (atEnd()) {
    fatalIOError(location(), fmt::format("{}: the value ends too early", context_));
  }
  return tokens_[i_];
}

const Token& TokenReader::next() {
  const Token& t = peek();
  ++i_;
  return t;
}

const Token& TokenReader::nextNumber(const std::string& what) {
  if (!atEnd()) {
    const Token& t = tokens_[i_];
    if (t.isNumber()) {
      ++i_;
      return t;
    }
    if (t.isWord() && isNonFiniteNumber(t.text)) {
      errorAt(t, fmt::format("'{}' is not a finite number; expected {}", t.text, what));
    }
  }
  expected(what);
}

void TokenReader::expectPunct(char c, const std::string& what) {
  if (atEnd() || !tokens_[i_].isPunct(c)) {
    expected(fmt::format("'{}' {}", c, what));
  }
  ++i_;
}

bool TokenReader::acceptPunct(char c) {
  if (!atEnd() && tokens_[i_].isPunct(c)) {
    ++i_;
    return true;
  }
  return false;
}

void TokenReader::expected(const std::string& what) const {
  if (atEnd()) {
    fatalIOError(location(), fmt::format("{}: expected {}, but the value ended", context_, what));
  }
  fatalIOError(tokens_[i_].loc,
               fmt::format("{}: expected {}, found {}", context_, what, tokens_[i_].describe()));
}

void TokenReader::errorAt(const Token& t, const std::string& message) const {
  fatalIOError(t.loc, fmt::format("{}: {}", context_, message));
}

void TokenReader::expectEnd(const std::string& what) const {
  if (atEnd()) return;
  const Token& t = tokens_[i_];
  fatalIOError(t.loc, fmt::format("{}: unexpected {} after {} (missing ';'?)", context_,
                                  t.describe(), what));
}

}  // namespace isph
