#pragma once
// An OpenFOAM-syntax dictionary: an ordered set of keyword entries, each a primitive
// value (a token stream) or a sub-dictionary, with typed getters whose errors name the
// file, line, keyword and what was expected.
//
//   Dictionary controlDict = Dictionary::readFile("system/controlDict");
//   double endTime = controlDict.get<double>("endTime");
//   double maxCo = controlDict.getOrDefault("maxCo", 0.2);   // default echoed in the log
//   std::string w = controlDict.getChoice("writeControl", {"timeStep", "runTime"});
//   controlDict.checkKeywords();   // unknown keywords: an error when one is a near miss of a
//                                  // keyword read ("did you mean endTime?"), else a warning
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/Log.hpp"
#include "core/dictionary/DictionaryLimits.hpp"
#include "core/dictionary/KeywordRecord.hpp"
#include "core/dictionary/Token.hpp"
#include "core/dictionary/ValueTraits.hpp"

namespace isph {

class Dictionary;


class Entry {
 public:
  Entry(std::string key, SourceLocation loc, std::vector<Token> tokens);
  Entry(std::string key, SourceLocation loc, Dictionary dict);
  Entry(const Entry& other);
  Entry& operator=(const Entry& other);
  Entry(Entry&&) noexcept;
  Entry& operator=(Entry&&) noexcept;
  ~Entry();

  const std::string& key() const { return key_; }
  const SourceLocation& location() const { return loc_; }
  bool isDict() const { return dict_ != nullptr; }
  const Dictionary& dict() const { return *dict_; }
  Dictionary& dict() { return *dict_; }
  const std::vector<Token>& tokens() const { return tokens_; }

 private:
  std::string key_;
  SourceLocation loc_;
  std::vector<Token> tokens_;
  std::unique_ptr<Dictionary> dict_;
};

class Dictionary {
 public:
  Dictionary() = default;
  explicit Dictionary(std::string name, SourceLocation loc = {});

  // Parse a file (with #include and $ substitution); FatalError on bad syntax.
  static Dictionary readFile(const std::filesystem::path& file);
  // The file's dictionary, or, when there is no such file, an empty one named after it (the
  // log says "<what> not found: using the defaults").
  static Dictionary readOptionalFile(const std::filesystem::path& file, const std::string& what);
  // Parse text; `fileName` is what error messages and relative #include paths use.
  static Dictionary parse(std::string_view text, const std::string& fileName);
  // Parse only the first entry (the FoamFile header of a field file); `end` receives the
  // byte offset just after it, where the data begins.
  static Dictionary parseHeader(std::string_view text, const std::string& fileName, std::size_t& end);

  const std::string& name() const { return name_; }
  const SourceLocation& location() const { return loc_; }

  bool found(std::string_view key) const { return findEntry(key) != nullptr; }
  bool isDict(std::string_view key) const;
  std::vector<std::string> keys() const;
  std::size_t size() const { return entries_.size(); }
  const std::vector<Entry>& entries() const { return entries_; }

  const Entry* findEntry(std::string_view key) const;
  // The entry or a FatalError naming this dictionary and what was expected.
  const Entry& entry(std::string_view key, const std::string& expected = {}) const;

  const Dictionary& subDict(std::string_view key) const;
  const Dictionary* findDict(std::string_view key) const;
  // A sub-dictionary, or an empty one (named, located at this dictionary) when absent.
  Dictionary subDictOrEmpty(std::string_view key) const;

  // Typed access. A leading dimension set ([0 1 -2 0 0 0 0]) and an OpenFOAM-1.x style
  // leading name equal to the keyword are skipped, as in `nu nu [0 2 -1 0 0 0 0] 1e-6;`.
  template <class T>
  T get(std::string_view key) const;
  template <class T>
  T getOrDefault(std::string_view key, const T& fallback) const;
  std::string getOrDefault(std::string_view key, const char* fallback) const {
    return getOrDefault<std::string>(key, std::string(fallback));
  }
  template <class T>
  std::optional<T> getOptional(std::string_view key) const;

  // A word from a fixed set ("did you mean ...?" on a near miss).
  std::string getChoice(std::string_view key, const std::vector<std::string>& choices) const;
  std::string getChoiceOrDefault(std::string_view key, const std::vector<std::string>& choices,
                                 const std::string& fallback) const;

  // The dimension set of an entry, if it has one.
  std::optional<DimensionSet> getDimensions(std::string_view key) const;

  // Every entry that the code never asked for: a FatalError when it is within two edits of a
  // keyword it did ask for (a misspelt keyword would otherwise leave its default in force:
  // "did you mean endTime?"), a warning otherwise. An entry used as a $variable is neither.
  // Call once a dictionary has been fully read.
  void checkKeywords(const std::vector<std::string>& alsoValid = {}) const;
  // Record that `key` is valid here although the code has not read it (yet).
  void markRead(std::string_view key) const { queried_.insert(std::string(key)); }
  // Record that `key` was used as a $variable (the parser does): no keyword of the code's.
  void markVariable(std::string_view key) const { variables_.insert(std::string(key)); }

  // Programmatic construction (used to write dictionaries such as <time>/uniform/time).
  template <class T>
  void set(std::string_view key, const T& value) {
    setRaw(key, ValueTraits<T>::write(value));
  }
  void set(std::string_view key, const char* value) { set(key, std::string(value)); }
  void setRaw(std::string_view key, std::string_view valueText);
  Dictionary& subDictOrAdd(std::string_view key);
  // Replaces (or, for two dictionaries, merges into) an entry of that key; constant time, as
  // is findEntry (a hash index beside the ordered entries), so that parsing is linear in the
  // number of entries.
  void add(Entry entry);
  bool remove(std::string_view key);

  // OpenFOAM syntax, entries in order; `indent` spaces before each line.
  std::string write(int indent = 0) const;

 private:
  std::string context(std::string_view key) const;
  TokenReader valueReader(const Entry& e, std::string_view key) const;
  void echoDefault(std::string_view key, const std::string& value) const;

  struct KeyHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view key) const { return std::hash<std::string_view>{}(key); }
  };

  std::string name_;
  SourceLocation loc_;
  std::vector<Entry> entries_;
  std::unordered_map<std::string, std::size_t, KeyHash, std::equal_to<>> index_;  // key -> entries_ position
  mutable std::set<std::string, std::less<>> queried_;
  mutable std::set<std::string, std::less<>> variables_;
};

// ---- template implementations ------------------------------------------------------

template <class T>
T Dictionary::get(std::string_view key) const {
  queried_.insert(std::string(key));
  recordKeyword(name_, key);
  const Entry& e = entry(key, ValueTraits<T>::expected());
  if (e.isDict()) {
    fatalIOError(e.location(), fmt::format("{}: expected {}, found a sub-dictionary", context(key),
                                           ValueTraits<T>::expected()));
  }
  TokenReader in = valueReader(e, key);
  T value = ValueTraits<T>::read(in);
  in.expectEnd("the value");
  return value;
}

template <class T>
std::optional<T> Dictionary::getOptional(std::string_view key) const {
  queried_.insert(std::string(key));
  recordKeyword(name_, key);
  if (!found(key)) return std::nullopt;
  return get<T>(key);
}

template <class T>
T Dictionary::getOrDefault(std::string_view key, const T& fallback) const {
  queried_.insert(std::string(key));
  if (keywordRecordOn()) recordDefault(name_, key, ValueTraits<T>::write(fallback));
  if (found(key)) return get<T>(key);
  echoDefault(key, ValueTraits<T>::write(fallback));
  return fallback;
}

}  // namespace isph
