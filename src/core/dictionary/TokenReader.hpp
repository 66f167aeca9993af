#pragma once
// A cursor over the tokens of one dictionary entry, used by the typed readers
// (ValueTraits) to parse values and to report errors at the offending token.
#include <string>
#include <vector>

#include "core/dictionary/Token.hpp"

namespace isph {

class TokenReader {
 public:
  // `context` names the entry for messages: "keyword 'endTime' in system/controlDict".
  TokenReader(const std::vector<Token>& tokens, std::string context, SourceLocation entryLocation);

  bool atEnd() const { return i_ >= tokens_.size(); }
  const Token& peek() const;  // error at the end of the entry
  const Token& next();
  // Consume a number and return it, or report that `what` was expected; a word spelled as a
  // number that is not finite (nan, inf, 1e400) is reported as "not a finite number".
  const Token& nextNumber(const std::string& what);
  // Consume the punctuation `c` or report that `what` expected it.
  void expectPunct(char c, const std::string& what);
  bool acceptPunct(char c);

  // Error at the current token (or at the end of the entry) saying what was expected.
  [[noreturn]] void expected(const std::string& what) const;
  [[noreturn]] void errorAt(const Token& t, const std::string& message) const;
  // Error when tokens remain after a complete value (usually a missing ';').
  void expectEnd(const std::string& what) const;

  const std::string& context() const { return context_; }
  SourceLocation location() const;

 private:
  const std::vector<Token>& tokens_;
  std::size_t i_ = 0;
  std::string context_;
  SourceLocation entryLocation_;
};

}  // namespace isph
