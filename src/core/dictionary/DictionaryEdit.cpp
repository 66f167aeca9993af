#include "core/dictionary/DictionaryEdit.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Strings.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/dictionary/Lexer.hpp"

namespace isph {

namespace {

// The byte offsets of an entry's value in `text`: from its first character to the ';'.
struct ValueSpan {
  std::size_t begin = 0, end = 0;
};

ValueSpan findValue(std::string_view text, const std::string& fileName, const SourceLocation& key) {
  Lexer lexer(text, std::make_shared<const std::string>(fileName));
  while (auto t = lexer.next()) {
    if (t->loc.line != key.line || t->loc.column != key.column) continue;
    ValueSpan span;
    span.begin = lexer.offset();
    while (span.begin < text.size() && std::string_view(" \t\r\n").find(text[span.begin]) != std::string_view::npos) {
      ++span.begin;
    }
    int depth = 0;
    while (auto v = lexer.next()) {
      if (v->isPunct('(') || v->isPunct('[') || v->isPunct('{')) ++depth;
      if (v->isPunct(')') || v->isPunct(']') || v->isPunct('}')) --depth;
      if (depth == 0 && v->isPunct(';')) {
        span.end = lexer.offset() - 1;
        return span;
      }
    }
    break;
  }
  fatalIOError(key, "cannot find the value of this entry in the file's text");
}

std::string spelled(const Dictionary& d, const std::string& key) {
  std::vector<std::string> words;
  for (const auto& t : d.entry(key).tokens()) words.push_back(t.spelling());
  return join(words, " ");
}

}  // namespace

std::string setEntryValue(std::string_view text, const std::string& fileName, const std::vector<std::string>& path,
                          const std::string& value) {
  if (path.empty()) fatalError("-set needs an -entry");
  const Dictionary dict = Dictionary::parse(text, fileName);
  const Dictionary* scope = &dict;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) scope = &scope->subDict(path[i]);
  const std::string& key = path.back();
  const std::string name = join(path, "/");
  std::string edited;
  if (const Entry* e = scope->findEntry(key)) {
    if (e->isDict()) {
      fatalIOError(e->location(), fmt::format("entry '{}' is a sub-dictionary: -set one of its entries", name));
    }
    if (!e->location().file || *e->location().file != fileName) {
      fatalIOError(e->location(), fmt::format("entry '{}' of {} comes from here (an #include): set it in that file",
                                              name, fileName));
    }
    const ValueSpan span = findValue(text, fileName, e->location());
    edited = std::string(text.substr(0, span.begin)) + value + std::string(text.substr(span.end));
  } else if (path.size() == 1) {
    edited = std::string(text);
    if (!edited.empty() && edited.back() != '\n') edited += '\n';
    edited += fmt::format("{:<15} {};\n", key, value);
  } else {
    fatalError(fmt::format("{}: no entry '{}' in dictionary {} (-set adds entries at the top level only)", fileName,
                           key, scope->name()));
  }
  // The new text must parse, with the entry holding the value given (not a $ expansion's).
  const Dictionary check = Dictionary::parse(edited, fileName);
  const Dictionary* s = &check;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) s = &s->subDict(path[i]);
  const Dictionary expected = Dictionary::parse(fmt::format("{} {};", key, value), "-set " + value);
  if (spelled(*s, key) != spelled(expected, key)) {
    fatalError(fmt::format("{}: after -set, '{}' reads '{}', not '{}' (a $ expansion?): the file is unchanged",
                           fileName, name, spelled(*s, key), spelled(expected, key)));
  }
  return edited;
}

}  // namespace isph
