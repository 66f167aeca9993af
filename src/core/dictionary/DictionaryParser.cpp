// Parsing of OpenFOAM dictionary syntax: entries, sub-dictionaries, lists, $ substitution
// (with scoping) and #include / #includeEtc / #includeIfPresent / #remove directives.
#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/EtcFiles.hpp"
#include "core/Strings.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/dictionary/Lexer.hpp"

namespace isph {

namespace {

constexpr int maxIncludeDepth = 32;

std::string readWholeFile(const std::filesystem::path& file, bool& ok) {
  std::ifstream in(file, std::ios::binary);
  ok = static_cast<bool>(in);
  if (!ok) return {};
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Expands $VAR and ${VAR} from the environment and a leading ~ in #include file names.
std::string expandEnvironment(const std::string& s, const SourceLocation& loc) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '~' && i == 0) {
      const char* home = std::getenv("HOME");
      out += home ? home : "";
    } else if (s[i] == '$') {
      std::string name;
      if (i + 1 < s.size() && s[i + 1] == '{') {
        const auto close = s.find('}', i + 2);
        if (close == std::string::npos) fatalIOError(loc, fmt::format("unterminated '${{' in \"{}\"", s));
        name = s.substr(i + 2, close - i - 2);
        i = close;
      } else {
        std::size_t j = i + 1;
        while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
        name = s.substr(i + 1, j - i - 1);
        i = j - 1;
      }
      const char* value = std::getenv(name.c_str());
      if (!value) fatalIOError(loc, fmt::format("environment variable '{}' in \"{}\" is not set", name, s));
      out += value;
    } else {
      out += s[i];
    }
  }
  return out;
}

class Parser {
 public:
  Parser(std::string_view text, std::shared_ptr<const std::string> file, std::vector<Dictionary*>& scopes,
         int includeDepth)
      : lexer_(text, file), file_(std::move(file)), scopes_(scopes), includeDepth_(includeDepth) {}

  // Parse entries into `dict` until the end of the text (or the closing '}' when braced).
  void parseBody(Dictionary& dict, const Token* openBrace, bool firstEntryOnly = false);
  std::size_t offset() const { return lexer_.offset(); }

 private:
  void parseEntry(Dictionary& dict, Token key);
  void parseDirective(Dictionary& dict, const Token& directive);
  void includeFile(Dictionary& dict, const std::filesystem::path& path, const Token& where, bool optional);
  const Entry& resolve(const Token& variable) const;
  const Entry* lookupPath(const Dictionary* start, std::size_t scopeIndex, std::string_view path,
                          bool searchUp) const;
  std::filesystem::path directory() const { return std::filesystem::path(*file_).parent_path(); }

  Lexer lexer_;
  std::shared_ptr<const std::string> file_;
  std::vector<Dictionary*>& scopes_;
  int includeDepth_;
};

void Parser::parseBody(Dictionary& dict, const Token* openBrace, bool firstEntryOnly) {
  scopes_.push_back(&dict);
  for (;;) {
    std::optional<Token> t = lexer_.next();
    if (!t) {
      if (openBrace) {
        fatalIOError(openBrace->loc, fmt::format("dictionary {} opened here is not closed: missing '}}'",
                                                 dict.name()));
      }
      break;
    }
    if (t->isPunct('}')) {
      if (openBrace) break;
      fatalIOError(t->loc, "unexpected '}' with no dictionary open");
    }
    if (t->isPunct(';')) continue;  // a stray ';' is harmless
    if (t->kind == TokenKind::Directive) {
      parseDirective(dict, *t);
    } else if (t->kind == TokenKind::Variable) {
      // `$dict;` at keyword position merges that dictionary's entries here.
      const Entry& source = resolve(*t);
      if (!source.isDict()) {
        fatalIOError(t->loc, fmt::format("'${}' names a value, not a dictionary; only a dictionary can be "
                                         "expanded at keyword position",
                                         t->text));
      }
      const Dictionary copy = source.dict();
      for (const auto& e : copy.entries()) dict.add(e);
      if (auto p = lexer_.peek(); p && p->isPunct(';')) lexer_.next();
    } else if (t->isWord() || t->isString() || t->isNumber()) {
      parseEntry(dict, std::move(*t));
    } else {
      fatalIOError(t->loc, fmt::format("expected a keyword, found {}", t->describe()));
    }
    if (firstEntryOnly) break;
  }
  scopes_.pop_back();
}

void Parser::parseEntry(Dictionary& dict, Token key) {
  std::optional<Token> t = lexer_.peek();
  if (t && t->isPunct('{')) {
    const Token open = *lexer_.next();
    Dictionary sub(dict.name().empty() ? key.text : dict.name() + "/" + key.text, key.loc);
    parseBody(sub, &open);
    dict.add(Entry(key.text, key.loc, std::move(sub)));
    return;
  }

  std::vector<Token> tokens;
  std::vector<Token> open;  // unclosed ( [ { within the value
  for (;;) {
    std::optional<Token> next = lexer_.next();
    if (!next) {
      if (!open.empty()) {
        fatalIOError(open.back().loc, fmt::format("'{}' opened here in the value of '{}' is not closed",
                                                  open.back().text, key.text));
      }
      const SourceLocation& at = tokens.empty() ? key.loc : tokens.back().loc;
      fatalIOError(at, fmt::format("missing ';' at the end of entry '{}'", key.text));
    }
    Token& tok = *next;
    if (open.empty()) {
      if (tok.isPunct(';')) break;
      if (tok.isPunct('}') || tok.isPunct(')') || tok.isPunct(']')) {
        if (tok.isPunct('}')) {
          const SourceLocation& at = tokens.empty() ? key.loc : tokens.back().loc;
          fatalIOError(at, fmt::format("missing ';' at the end of entry '{}'", key.text));
        }
        fatalIOError(tok.loc, fmt::format("unexpected '{}' in the value of '{}'", tok.text, key.text));
      }
      // A new line that starts with a word after a complete value is almost always the next
      // keyword after a forgotten ';'.
      if (!tokens.empty() && tok.loc.line > tokens.back().loc.line &&
          (tok.isWord() || tok.isString() || tok.kind == TokenKind::Variable ||
           (tok.isNumber() && !(lexer_.peek() && (lexer_.peek()->isPunct('(') || lexer_.peek()->isPunct('{')))))) {
        fatalIOError(tokens.back().loc, fmt::format("missing ';' at the end of entry '{}' (the next line "
                                                    "starts with {})",
                                                    key.text, tok.describe()));
      }
    }
    if (tok.kind == TokenKind::Directive) {
      fatalIOError(tok.loc, fmt::format("directive '#{}' cannot appear inside the value of '{}'", tok.text,
                                        key.text));
    }
    if (tok.kind == TokenKind::Variable) {
      const Entry& source = resolve(tok);
      if (source.isDict()) {
        std::optional<Token> after = lexer_.peek();
        if (tokens.empty() && open.empty() && after && after->isPunct(';')) {
          lexer_.next();
          Dictionary copy = source.dict();
          dict.add(Entry(key.text, key.loc, std::move(copy)));
          return;
        }
        fatalIOError(tok.loc, fmt::format("'${}' is a dictionary and can only stand alone as a value", tok.text));
      }
      tokens.insert(tokens.end(), source.tokens().begin(), source.tokens().end());
      continue;
    }
    if (tok.isPunct('(') || tok.isPunct('[') || tok.isPunct('{')) {
      open.push_back(tok);
    } else if (tok.isPunct(')') || tok.isPunct(']') || tok.isPunct('}')) {
      const char expected = open.back().text[0] == '(' ? ')' : open.back().text[0] == '[' ? ']' : '}';
      if (tok.text[0] != expected) {
        fatalIOError(tok.loc, fmt::format("'{}' does not match '{}' opened at line {} in the value of '{}'",
                                          tok.text, open.back().text, open.back().loc.line, key.text));
      }
      open.pop_back();
    }
    tokens.push_back(std::move(tok));
  }
  dict.add(Entry(key.text, key.loc, std::move(tokens)));
}

void Parser::parseDirective(Dictionary& dict, const Token& directive) {
  const std::string& name = directive.text;
  if (name == "include" || name == "includeEtc" || name == "includeIfPresent") {
    std::optional<Token> file = lexer_.next();
    if (!file || !(file->isString() || file->isWord())) {
      fatalIOError(directive.loc, fmt::format("#{} must be followed by a quoted file name", name));
    }
    std::filesystem::path path = expandEnvironment(file->text, file->loc);
    if (name == "includeEtc") {
      path = etcDirectory() / path;
    } else if (path.is_relative()) {
      path = directory() / path;
    }
    includeFile(dict, path, *file, name == "includeIfPresent");
  } else if (name == "remove") {
    std::optional<Token> t = lexer_.next();
    if (t && t->isPunct('(')) {
      for (t = lexer_.next(); t && !t->isPunct(')'); t = lexer_.next()) dict.remove(t->text);
      if (!t) fatalIOError(directive.loc, "#remove ( ... ): the list is not closed");
    } else if (t && (t->isWord() || t->isString())) {
      dict.remove(t->text);
    } else {
      fatalIOError(directive.loc, "#remove must be followed by a keyword or a list of keywords");
    }
  } else {
    fatalIOError(directive.loc,
                 fmt::format("unknown directive '#{}'; expected #include, #includeEtc, #includeIfPresent or "
                             "#remove{}",
                             name, didYouMean(name, {"include", "includeEtc", "includeIfPresent", "remove"})));
  }
  if (auto p = lexer_.peek(); p && p->isPunct(';')) lexer_.next();
}

void Parser::includeFile(Dictionary& dict, const std::filesystem::path& path, const Token& where, bool optional) {
  if (includeDepth_ >= maxIncludeDepth) {
    fatalIOError(where.loc, fmt::format("#include nested more than {} deep (a file including itself?)",
                                        maxIncludeDepth));
  }
  bool ok = false;
  const std::string text = readWholeFile(path, ok);
  if (!ok) {
    if (optional) return;
    fatalIOError(where.loc, fmt::format("cannot open the #include file \"{}\" (looked for {})", where.text,
                                        path.lexically_normal().string()));
  }
  auto file = std::make_shared<const std::string>(path.lexically_normal().string());
  Parser inner(text, file, scopes_, includeDepth_ + 1);
  scopes_.pop_back();  // the included body continues the current dictionary's scope
  inner.parseBody(dict, nullptr);
  scopes_.push_back(&dict);
}

const Entry* Parser::lookupPath(const Dictionary* start, std::size_t scopeIndex, std::string_view path,
                                bool searchUp) const {
  // The whole name first (keys may contain '.' or '/'), then component by component.
  for (char separator : {'\0', '/', '.'}) {
    std::string_view first = path;
    std::string_view rest;
    if (separator) {
      const auto cut = path.find(separator);
      if (cut == std::string_view::npos) continue;
      first = path.substr(0, cut);
      rest = path.substr(cut + 1);
    }
    const Entry* e = nullptr;
    if (searchUp) {
      for (std::size_t k = scopeIndex + 1; k-- > 0 && !e;) e = scopes_[k]->findEntry(first);
    } else {
      e = start->findEntry(first);
    }
    if (!e) continue;
    if (!separator) return e;
    if (!e->isDict()) continue;
    if (const Entry* found = lookupPath(&e->dict(), 0, rest, false)) return found;
  }
  return nullptr;
}

const Entry& Parser::resolve(const Token& variable) const {
  std::string_view name = variable.text;
  std::size_t scope = scopes_.size() - 1;
  bool searchUp = true;
  if (name.starts_with(':') || name.starts_with('/')) {  // $:a.b  $/a/b : from the top level
    name.remove_prefix(1);
    scope = 0;
    searchUp = false;
  } else if (name.starts_with("..")) {  // $..a (dots: one level up per extra dot), $../a
    while (name.starts_with("../")) {
      name.remove_prefix(3);
      if (scope == 0) fatalIOError(variable.loc, fmt::format("'${}' goes above the top level", variable.text));
      --scope;
    }
    if (name.starts_with('.')) {
      std::size_t dots = 0;
      while (dots < name.size() && name[dots] == '.') ++dots;
      name.remove_prefix(dots);
      if (dots - 1 > scope) fatalIOError(variable.loc, fmt::format("'${}' goes above the top level", variable.text));
      scope -= dots - 1;
    }
    searchUp = false;
  }
  const Entry* e = searchUp ? lookupPath(nullptr, scope, name, true) : lookupPath(scopes_[scope], scope, name, false);
  if (!e) {
    std::vector<std::string> candidates;
    for (const Dictionary* d : scopes_) {
      const auto keys = d->keys();
      candidates.insert(candidates.end(), keys.begin(), keys.end());
    }
    fatalIOError(variable.loc, fmt::format("undefined variable '${}'{}", variable.text,
                                           didYouMean(name, candidates)));
  }
  return *e;
}

}  // namespace

Dictionary Dictionary::readFile(const std::filesystem::path& file) {
  bool ok = false;
  const std::string text = readWholeFile(file, ok);
  if (!ok) {
    fatalError(fmt::format("cannot open file {}\n    (does the case have it? {})", file.string(),
                           std::filesystem::exists(file) ? "it exists but cannot be read" : "no such file"));
  }
  return parse(text, file.string());
}

Dictionary Dictionary::parse(std::string_view text, const std::string& fileName) {
  auto file = std::make_shared<const std::string>(fileName);
  Dictionary dict(fileName, SourceLocation{file, 0, 0});
  std::vector<Dictionary*> scopes;
  Parser parser(text, file, scopes, 0);
  parser.parseBody(dict, nullptr);
  return dict;
}

Dictionary Dictionary::parseHeader(std::string_view text, const std::string& fileName, std::size_t& end) {
  auto file = std::make_shared<const std::string>(fileName);
  Dictionary dict(fileName, SourceLocation{file, 0, 0});
  std::vector<Dictionary*> scopes;
  Parser parser(text, file, scopes, 0);
  parser.parseBody(dict, nullptr, true);
  end = parser.offset();
  return dict;
}

}  // namespace isph
