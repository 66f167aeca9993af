#include "core/dictionary/ValueTraits.hpp"

#include <charconv>

#include "core/dictionary/Lexer.hpp"

namespace isph {

std::string formatScalar(double value) {
  char buffer[64];
  // Shortest round-trip representation; integers print without a decimal point.
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

bool ValueTraits<bool>::read(TokenReader& in) {
  const Token& t = in.peek();
  if (t.isWord()) {
    static const char* yes[] = {"on", "yes", "true", "y", "t"};
    static const char* no[] = {"off", "no", "false", "n", "f", "none"};
    for (const char* w : yes) {
      if (t.text == w) {
        in.next();
        return true;
      }
    }
    for (const char* w : no) {
      if (t.text == w) {
        in.next();
        return false;
      }
    }
  } else if (t.isNumber() && t.isInteger && (t.number == 0 || t.number == 1)) {
    in.next();
    return t.number != 0;
  }
  in.expected(expected());
}

std::string ValueTraits<std::string>::write(const std::string& v) {
  // A word when it lexes back as a single word, else a quoted string.
  bool plain = !v.empty();
  for (char c : v) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '"' || c == ';' || c == '{' || c == '}' ||
        c == '(' || c == ')' || c == '[' || c == ']' || c == '$' || c == '#' || c == '/') {
      plain = false;
    }
  }
  double number;
  bool integer;
  if (plain && !parseNumber(v, number, integer)) return v;
  Token t;
  t.kind = TokenKind::String;
  t.text = v;
  return t.spelling();
}

DimensionSet ValueTraits<DimensionSet>::read(TokenReader& in) {
  in.expectPunct('[', "opening a dimension set");
  DimensionSet d;
  int n = 0;
  while (!in.atEnd() && !in.peek().isPunct(']')) {
    const Token& t = in.peek();
    if (n >= 7) in.errorAt(t, "a dimension set has at most 7 exponents");
    d.exponents[static_cast<std::size_t>(n++)] = in.nextNumber("numeric exponents in the dimension set").number;
  }
  in.expectPunct(']', "closing the dimension set");
  if (n != 5 && n != 7) {
    in.expected("5 or 7 exponents in the dimension set [M L T Θ N I J]");
  }
  return d;
}

std::string ValueTraits<DimensionSet>::write(const DimensionSet& d) {
  std::string out = "[";
  for (std::size_t k = 0; k < 7; ++k) {
      if (k) out += ' ';
      out += formatScalar(d.exponents[k]);
    }
  return out + "]";
}

}  // namespace isph
