#pragma once
// One lexical token of OpenFOAM dictionary syntax, with the place it was read from.
#include <string>

#include "core/Error.hpp"

namespace isph {

enum class TokenKind {
  Word,       // endTime, adjustableRunTime, List<scalar>
  String,     // "quoted text" (text holds the unquoted content)
  Number,     // 1, -2.5e-3 (text keeps the spelling, number the value)
  Punct,      // one of ; { } ( ) [ ]
  Variable,   // $name, $sub/name, $:a.b, ${name} (text holds the name without '$')
  Directive,  // #include, #includeEtc (text holds the name without '#')
};

struct Token {
  TokenKind kind = TokenKind::Word;
  std::string text;
  double number = 0.0;
  bool isInteger = false;
  SourceLocation loc;

  bool isPunct(char c) const { return kind == TokenKind::Punct && text.size() == 1 && text[0] == c; }
  bool isWord() const { return kind == TokenKind::Word; }
  bool isNumber() const { return kind == TokenKind::Number; }
  bool isString() const { return kind == TokenKind::String; }

  // "word 'abc'", "number 1.5", "'('" for error messages.
  std::string describe() const;
  // The token as it is written in a dictionary (strings re-quoted).
  std::string spelling() const;
};

}  // namespace isph
