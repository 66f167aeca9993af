// Parsing of OpenFOAM dictionary syntax: entries, sub-dictionaries, lists, $ substitution
// (with scoping) and #include / #includeEtc / #includeIfPresent / #remove directives.
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <set>

#include "core/EtcFiles.hpp"
#include "core/Strings.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/dictionary/Lexer.hpp"
#include "core/io/ReadFile.hpp"

namespace isph {

namespace {

constexpr int maxIncludeDepth = 32;

// The text of a dictionary file: a regular file within DictionaryLimits (FatalError otherwise).
std::string readDictionaryText(const std::filesystem::path& file) {
  return readWholeFile(file, DictionaryLimits::maxFileBytes, "a dictionary");
}

// How deep the sub-dictionaries of `d` go (0: none) and how many entries it holds in all.
int depthOf(const Dictionary& d) {
  int depth = 0;
  for (const auto& e : d.entries()) {
    if (e.isDict()) depth = std::max(depth, 1 + depthOf(e.dict()));
  }
  return depth;
}

std::size_t sizeOf(const Dictionary& d) {
  std::size_t n = d.size();
  for (const auto& e : d.entries()) {
    if (e.isDict()) n += sizeOf(e.dict());
  }
  return n;
}

// What one parse (a file and its #includes) has used of the limits.
struct ParseBudget {
  std::size_t bytes = 0;
  std::size_t substituted = 0;
  void substitute(std::size_t n, const Token& variable) {
    substituted += n;
    if (substituted > DictionaryLimits::maxSubstituted) {
      fatalIOError(variable.loc, fmt::format("'${}': the $ substitutions of this dictionary copy more than {} "
                                             "entries and tokens (substitutions of substitutions?)",
                                             variable.text, DictionaryLimits::maxSubstituted));
    }
  }
  void add(std::size_t n, const SourceLocation& where, const std::filesystem::path& file) {
    bytes += n;
    if (bytes > DictionaryLimits::maxTotalBytes) {
      fatalIOError(where, fmt::format("#include \"{}\": the dictionary and its #include files hold more than "
                                      "the {} MiB one dictionary may hold (a file including itself?)",
                                      file.string(), DictionaryLimits::maxTotalBytes >> 20));
    }
  }
};

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
  // `nesting`: the sub-dictionaries open around the text (an #include continues the
  // nesting of the dictionary it stands in).
  Parser(std::string_view text, std::shared_ptr<const std::string> file, std::vector<Dictionary*>& scopes,
         int includeDepth, int nesting, ParseBudget& budget)
      : lexer_(text, file),
        file_(std::move(file)),
        scopes_(scopes),
        includeDepth_(includeDepth),
        nesting_(nesting),
        budget_(budget) {}

  // Parse entries into `dict` until the end of the text (or the closing '}' when braced).
  void parseBody(Dictionary& dict, const Token* openBrace, bool firstEntryOnly = false);
  std::size_t offset() const { return lexer_.offset(); }

 private:
  // `written`: the keywords written so far in this dictionary's own text (not those of an
  // #include or a $ expansion, which an entry may override): a second one is an error.
  void parseEntry(Dictionary& dict, Token key, std::set<std::string, std::less<>>& written);
  void parseDirective(Dictionary& dict, const Token& directive, std::set<std::string, std::less<>>& written);
  void includeFile(Dictionary& dict, const std::filesystem::path& path, const Token& where, bool optional);
  const Entry& resolve(const Token& variable) const;
  const Entry* lookupPath(const Dictionary* start, std::size_t scopeIndex, std::string_view path,
                          bool searchUp) const;
  std::filesystem::path directory() const { return std::filesystem::path(*file_).parent_path(); }

  // FatalError at `where` when `depth` levels are more than DictionaryLimits::maxNesting.
  static void checkNesting(int depth, const SourceLocation& where, const std::string& what);

  Lexer lexer_;
  std::shared_ptr<const std::string> file_;
  std::vector<Dictionary*>& scopes_;
  int includeDepth_;
  int nesting_;
  ParseBudget& budget_;
};

void Parser::checkNesting(int depth, const SourceLocation& where, const std::string& what) {
  if (depth <= DictionaryLimits::maxNesting) return;
  fatalIOError(where, fmt::format("{} nested more than {} levels deep; no case needs so many (a missing '}}' "
                                  "or ')'?)",
                                  what, DictionaryLimits::maxNesting));
}

void Parser::parseBody(Dictionary& dict, const Token* openBrace, bool firstEntryOnly) {
  scopes_.push_back(&dict);
  std::set<std::string, std::less<>> written;
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
      parseDirective(dict, *t, written);
    } else if (t->kind == TokenKind::Variable) {
      // `$dict;` at keyword position merges that dictionary's entries here.
      const Entry& source = resolve(*t);
      if (!source.isDict()) {
        fatalIOError(t->loc, fmt::format("'${}' names a value, not a dictionary; only a dictionary can be "
                                         "expanded at keyword position",
                                         t->text));
      }
      checkNesting(nesting_ + depthOf(source.dict()), t->loc,
                   fmt::format("'${}' expands to sub-dictionaries", t->text));
      budget_.substitute(sizeOf(source.dict()), *t);
      const Dictionary copy = source.dict();
      for (const auto& e : copy.entries()) dict.add(e);
      if (auto p = lexer_.peek(); p && p->isPunct(';')) lexer_.next();
    } else if (t->isWord() || t->isString() || t->isNumber()) {
      parseEntry(dict, std::move(*t), written);
    } else {
      fatalIOError(t->loc, fmt::format("expected a keyword, found {}", t->describe()));
    }
    if (firstEntryOnly) break;
  }
  scopes_.pop_back();
}

void Parser::parseEntry(Dictionary& dict, Token key, std::set<std::string, std::less<>>& written) {
  if (!written.insert(key.text).second) {
    const Entry* first = dict.findEntry(key.text);
    fatalIOError(key.loc, fmt::format("keyword '{}' is given twice in dictionary {}{}: which one was meant? "
                                      "(Keep one; an entry from an #include may be overridden.)",
                                      key.text, dict.name(),
                                      first && first->location().known()
                                          ? fmt::format(" (first at line {})", first->location().line)
                                          : std::string()));
  }
  std::optional<Token> t = lexer_.peek();
  if (t && t->isPunct('{')) {
    const Token open = *lexer_.next();
    checkNesting(nesting_ + 1, open.loc, fmt::format("sub-dictionary '{}' is", key.text));
    Dictionary sub(dict.name().empty() ? key.text : dict.name() + "/" + key.text, key.loc);
    ++nesting_;
    parseBody(sub, &open);
    --nesting_;
    dict.add(Entry(key.text, key.loc, std::move(sub)));
    return;
  }

  std::vector<Token> tokens;
  std::vector<Token> open;  // unclosed ( [ { within the value
  // Where the last token of the value was read (a $ substitution's tokens keep the place they
  // came from, which may be lines above).
  SourceLocation last = key.loc;
  for (;;) {
    std::optional<Token> next = lexer_.next();
    if (!next) {
      if (!open.empty()) {
        fatalIOError(open.back().loc, fmt::format("'{}' opened here in the value of '{}' is not closed",
                                                  open.back().text, key.text));
      }
      fatalIOError(last, fmt::format("missing ';' at the end of entry '{}'", key.text));
    }
    Token& tok = *next;
    if (open.empty()) {
      if (tok.isPunct(';')) break;
      if (tok.isPunct('}') || tok.isPunct(')') || tok.isPunct(']')) {
        if (tok.isPunct('}')) fatalIOError(last, fmt::format("missing ';' at the end of entry '{}'", key.text));
        fatalIOError(tok.loc, fmt::format("unexpected '{}' in the value of '{}'", tok.text, key.text));
      }
      // A new line that starts with a word after a complete value is almost always the next
      // keyword after a forgotten ';'.
      if (!tokens.empty() && tok.loc.line > last.line &&
          (tok.isWord() || tok.isString() || tok.kind == TokenKind::Variable ||
           (tok.isNumber() && !(lexer_.peek() && (lexer_.peek()->isPunct('(') || lexer_.peek()->isPunct('{')))))) {
        fatalIOError(last, fmt::format("missing ';' at the end of entry '{}' (the next line "
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
          checkNesting(nesting_ + 1 + depthOf(source.dict()), tok.loc,
                       fmt::format("'${}' expands to sub-dictionaries", tok.text));
          budget_.substitute(sizeOf(source.dict()), tok);
          Dictionary copy = source.dict();
          dict.add(Entry(key.text, key.loc, std::move(copy)));
          return;
        }
        fatalIOError(tok.loc, fmt::format("'${}' is a dictionary and can only stand alone as a value", tok.text));
      }
      budget_.substitute(source.tokens().size(), tok);
      tokens.insert(tokens.end(), source.tokens().begin(), source.tokens().end());
      last = tok.loc;
      continue;
    }
    if (tok.isPunct('(') || tok.isPunct('[') || tok.isPunct('{')) {
      open.push_back(tok);
      checkNesting(static_cast<int>(open.size()), tok.loc, fmt::format("the value of '{}' has brackets", key.text));
    } else if (tok.isPunct(')') || tok.isPunct(']') || tok.isPunct('}')) {
      const char expected = open.back().text[0] == '(' ? ')' : open.back().text[0] == '[' ? ']' : '}';
      if (tok.text[0] != expected) {
        fatalIOError(tok.loc, fmt::format("'{}' does not match '{}' opened at line {} in the value of '{}'",
                                          tok.text, open.back().text, open.back().loc.line, key.text));
      }
      open.pop_back();
    }
    last = tok.loc;
    tokens.push_back(std::move(tok));
  }
  dict.add(Entry(key.text, key.loc, std::move(tokens)));
}

void Parser::parseDirective(Dictionary& dict, const Token& directive, std::set<std::string, std::less<>>& written) {
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
      for (t = lexer_.next(); t && !t->isPunct(')'); t = lexer_.next()) {
        dict.remove(t->text);
        written.erase(t->text);
      }
      if (!t) fatalIOError(directive.loc, "#remove ( ... ): the list is not closed");
    } else if (t && (t->isWord() || t->isString())) {
      dict.remove(t->text);
      written.erase(t->text);
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
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    if (optional) return;
    fatalIOError(where.loc, fmt::format("cannot open the #include file \"{}\" (looked for {})", where.text,
                                        path.lexically_normal().string()));
  }
  std::string text;
  try {
    text = readDictionaryText(path);
  } catch (const FatalError& e) {  // not a regular file, too large, unreadable: said where it is included
    fatalIOError(where.loc, fmt::format("#include \"{}\": {}", where.text, e.what()));
  }
  budget_.add(text.size(), where.loc, path);
  auto file = std::make_shared<const std::string>(path.lexically_normal().string());
  Parser inner(text, file, scopes_, includeDepth_ + 1, nesting_, budget_);
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
    const Dictionary* holder = start;
    if (searchUp) {
      for (std::size_t k = scopeIndex + 1; k-- > 0 && !e;) {
        holder = scopes_[k];
        e = holder->findEntry(first);
      }
    } else {
      e = start->findEntry(first);
    }
    if (!e) continue;
    holder->markVariable(first);  // a name used as $variable is no misspelt keyword
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
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    fatalError(fmt::format("cannot open file {}\n    (does the case have it? no such file)", file.string()));
  }
  return parse(readDictionaryText(file), file.string());
}

Dictionary Dictionary::readOptionalFile(const std::filesystem::path& file, const std::string& what) {
  if (std::filesystem::exists(file)) return readFile(file);
  info("    {} not found: using the defaults", what);
  return Dictionary(file.string());
}

Dictionary Dictionary::parse(std::string_view text, const std::string& fileName) {
  auto file = std::make_shared<const std::string>(fileName);
  Dictionary dict(fileName, SourceLocation{file, 0, 0});
  std::vector<Dictionary*> scopes;
  ParseBudget budget{text.size()};
  Parser parser(text, file, scopes, 0, 0, budget);
  parser.parseBody(dict, nullptr);
  return dict;
}

Dictionary Dictionary::parseHeader(std::string_view text, const std::string& fileName, std::size_t& end) {
  auto file = std::make_shared<const std::string>(fileName);
  Dictionary dict(fileName, SourceLocation{file, 0, 0});
  std::vector<Dictionary*> scopes;
  ParseBudget budget{0};
  Parser parser(text, file, scopes, 0, 0, budget);
  parser.parseBody(dict, nullptr, true);
  end = parser.offset();
  return dict;
}

}  // namespace isph
