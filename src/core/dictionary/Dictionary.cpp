#include "core/dictionary/Dictionary.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Strings.hpp"
#include "core/dictionary/Lexer.hpp"

namespace isph {

// ---- Entry ---------------------------------------------------------------------------

Entry::Entry(std::string key, SourceLocation loc, std::vector<Token> tokens)
    : key_(std::move(key)), loc_(std::move(loc)), tokens_(std::move(tokens)) {}

Entry::Entry(std::string key, SourceLocation loc, Dictionary dict)
    : key_(std::move(key)), loc_(std::move(loc)), dict_(std::make_unique<Dictionary>(std::move(dict))) {}

Entry::Entry(const Entry& other)
    : key_(other.key_),
      loc_(other.loc_),
      tokens_(other.tokens_),
      dict_(other.dict_ ? std::make_unique<Dictionary>(*other.dict_) : nullptr) {}

Entry& Entry::operator=(const Entry& other) {
  if (this != &other) {
    Entry copy(other);
    *this = std::move(copy);
  }
  return *this;
}

Entry::Entry(Entry&&) noexcept = default;
Entry& Entry::operator=(Entry&&) noexcept = default;
Entry::~Entry() = default;

// ---- Dictionary: lookup --------------------------------------------------------------

Dictionary::Dictionary(std::string name, SourceLocation loc) : name_(std::move(name)), loc_(std::move(loc)) {}

const Entry* Dictionary::findEntry(std::string_view key) const {
  const auto it = index_.find(key);
  return it == index_.end() ? nullptr : &entries_[it->second];
}

bool Dictionary::isDict(std::string_view key) const {
  const Entry* e = findEntry(key);
  return e && e->isDict();
}

std::vector<std::string> Dictionary::keys() const {
  std::vector<std::string> out;
  out.reserve(entries_.size());
  for (const auto& e : entries_) out.push_back(e.key());
  return out;
}

std::string Dictionary::context(std::string_view key) const {
  return fmt::format("keyword '{}' in dictionary {}", key, name_.empty() ? "<unnamed>" : name_);
}

const Entry& Dictionary::entry(std::string_view key, const std::string& expected) const {
  queried_.insert(std::string(key));
  if (const Entry* e = findEntry(key)) return *e;
  std::string message = fmt::format("keyword '{}' is undefined in dictionary {}{}", key,
                                    name_.empty() ? "<unnamed>" : name_, didYouMean(key, keys()));
  if (!expected.empty()) message += fmt::format("\n    expected: {} {};", key, expected);
  fatalIOError(loc_, std::move(message));
}

const Dictionary* Dictionary::findDict(std::string_view key) const {
  queried_.insert(std::string(key));
  const Entry* e = findEntry(key);
  return e && e->isDict() ? &e->dict() : nullptr;
}

const Dictionary& Dictionary::subDict(std::string_view key) const {
  const Entry& e = entry(key, "a sub-dictionary { ... }");
  if (!e.isDict()) {
    fatalIOError(e.location(), fmt::format("{}: expected a sub-dictionary {{ ... }}, found a value",
                                           context(key)));
  }
  return e.dict();
}

Dictionary Dictionary::subDictOrEmpty(std::string_view key) const {
  if (const Dictionary* d = findDict(key)) return *d;
  const Entry* e = findEntry(key);
  if (e) {
    fatalIOError(e->location(), fmt::format("{}: expected a sub-dictionary {{ ... }}, found a value",
                                            context(key)));
  }
  return Dictionary(name_ + "/" + std::string(key), loc_);
}

TokenReader Dictionary::valueReader(const Entry& e, std::string_view key) const {
  TokenReader in(e.tokens(), context(key), e.location());
  // OpenFOAM-1.x style `nu nu [0 2 -1 0 0 0 0] 1e-6;`: skip the repeated name.
  const auto& t = e.tokens();
  if (t.size() >= 2 && t[0].isWord() && t[0].text == key && t[1].isPunct('[')) in.next();
  // Skip a dimension set; get<DimensionSet> goes through getDimensions instead.
  if (!in.atEnd() && in.peek().isPunct('[')) ValueTraits<DimensionSet>::read(in);
  return in;
}

std::optional<DimensionSet> Dictionary::getDimensions(std::string_view key) const {
  const Entry& e = entry(key, "a dimensioned value [M L T Θ N I J] value");
  if (e.isDict()) return std::nullopt;
  TokenReader in(e.tokens(), context(key), e.location());
  const auto& t = e.tokens();
  if (t.size() >= 2 && t[0].isWord() && t[0].text == key && t[1].isPunct('[')) in.next();
  if (in.atEnd() || !in.peek().isPunct('[')) return std::nullopt;
  return ValueTraits<DimensionSet>::read(in);
}

std::string Dictionary::getChoice(std::string_view key, const std::vector<std::string>& choices) const {
  queried_.insert(std::string(key));
  recordChoices(name_, key, choices);
  const std::string expected = "one of " + join(choices, "|");
  const Entry& e = entry(key, expected);
  if (e.isDict()) fatalIOError(e.location(), fmt::format("{}: expected {}, found a sub-dictionary", context(key), expected));
  TokenReader in = valueReader(e, key);
  const Token& t = in.peek();
  if (!t.isWord()) in.expected(expected);
  if (std::find(choices.begin(), choices.end(), t.text) == choices.end()) {
    in.errorAt(t, fmt::format("'{}' is not valid; expected {}{}", t.text, expected, didYouMean(t.text, choices)));
  }
  in.next();
  in.expectEnd("the value");
  return t.text;
}

std::string Dictionary::getChoiceOrDefault(std::string_view key, const std::vector<std::string>& choices,
                                           const std::string& fallback) const {
  queried_.insert(std::string(key));
  recordChoices(name_, key, choices);
  recordDefault(name_, key, fallback);
  if (found(key)) return getChoice(key, choices);
  echoDefault(key, fallback);
  return fallback;
}

void Dictionary::echoDefault(std::string_view key, const std::string& value) const {
  const std::string where = name_.empty() ? "<unnamed>" : name_;
  echoDefaultOnce(where + "/" + std::string(key),
                  fmt::format("    default: {} {};  ({})", key, value, where));
}

void Dictionary::checkKeywords(const std::vector<std::string>& alsoValid) const {
  std::vector<std::string> valid(queried_.begin(), queried_.end());
  valid.insert(valid.end(), alsoValid.begin(), alsoValid.end());
  const std::set<std::string_view> validSet(valid.begin(), valid.end());
  // A few warnings say what is wrong; thousands (a data file read as a dictionary) bury it.
  constexpr std::size_t maxWarnings = 20;
  constexpr std::size_t maxTypoEdits = 2;
  std::size_t unknown = 0;
  for (const auto& e : entries_) {
    if (e.key() == "FoamFile" || validSet.count(e.key()) || variables_.count(e.key())) continue;
    if (const std::string near = nearestWithin(e.key(), valid, maxTypoEdits); !near.empty()) {
      fatalIOError(e.location(),
                   fmt::format("unknown keyword '{}' in dictionary {} (did you mean {}?): a misspelt keyword "
                               "would leave the default of {} in force. (A name used only as a $variable "
                               "is allowed.)",
                               e.key(), name_, near, near));
    }
    if (++unknown > maxWarnings) continue;
    warning(fmt::format("unknown keyword '{}' in dictionary {} is ignored{}", e.key(), name_,
                        didYouMean(e.key(), valid)),
            e.location());
  }
  if (unknown > maxWarnings) {
    warning(fmt::format("{} more unknown keywords in dictionary {} are ignored", unknown - maxWarnings, name_),
            loc_);
  }
}

// ---- Dictionary: construction and writing --------------------------------------------

void Dictionary::add(Entry entry) {
  if (const auto it = index_.find(entry.key()); it != index_.end()) {
    Entry& e = entries_[it->second];
    if (e.isDict() && entry.isDict()) {
      for (const auto& sub : entry.dict().entries()) e.dict().add(sub);
    } else {
      e = std::move(entry);
    }
    return;
  }
  index_.emplace(entry.key(), entries_.size());
  entries_.push_back(std::move(entry));
}

bool Dictionary::remove(std::string_view key) {
  const auto it = index_.find(key);
  if (it == index_.end()) return false;
  const std::size_t at = it->second;
  entries_.erase(entries_.begin() + static_cast<std::ptrdiff_t>(at));
  index_.erase(it);
  for (auto& [k, position] : index_) {
    if (position > at) --position;
  }
  return true;
}

void Dictionary::setRaw(std::string_view key, std::string_view valueText) {
  auto file = std::make_shared<const std::string>(fmt::format("{}/{}", name_, key));
  Lexer lexer(valueText, file);
  std::vector<Token> tokens;
  while (auto t = lexer.next()) tokens.push_back(std::move(*t));
  add(Entry(std::string(key), SourceLocation{file, 0, 0}, std::move(tokens)));
}

Dictionary& Dictionary::subDictOrAdd(std::string_view key) {
  if (const auto it = index_.find(key); it != index_.end() && entries_[it->second].isDict()) {
    return entries_[it->second].dict();
  }
  add(Entry(std::string(key), loc_, Dictionary(name_ + "/" + std::string(key), loc_)));
  return entries_[index_.find(key)->second].dict();
}

namespace {

bool opens(const Token& t) { return t.isPunct('(') || t.isPunct('[') || t.isPunct('{'); }
bool closes(const Token& t) { return t.isPunct(')') || t.isPunct(']') || t.isPunct('}'); }

std::string writeTokens(const std::vector<Token>& tokens) {
  std::string out;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (i > 0 && !opens(tokens[i - 1]) && !closes(tokens[i]) &&
        !(tokens[i].isPunct('(') && tokens[i - 1].isNumber() && tokens[i - 1].isInteger)) {
      out += ' ';
    }
    out += tokens[i].spelling();
  }
  return out;
}

}  // namespace

std::string Dictionary::write(int indent) const {
  const std::string pad(static_cast<std::size_t>(indent), ' ');
  std::size_t width = 0;
  for (const auto& e : entries_) {
    if (!e.isDict()) width = std::max(width, e.key().size());
  }
  width = std::max<std::size_t>(width + 1, 12);
  std::string out;
  for (const auto& e : entries_) {
    const std::string key = ValueTraits<std::string>::write(e.key());
    if (e.isDict()) {
      out += fmt::format("{}{}\n{}{{\n{}{}}}\n", pad, key, pad, e.dict().write(indent + 4), pad);
    } else if (e.tokens().empty()) {
      out += fmt::format("{}{};\n", pad, key);
    } else {
      out += fmt::format("{}{:<{}}{};\n", pad, key, width, writeTokens(e.tokens()));
    }
  }
  return out;
}

}  // namespace isph
