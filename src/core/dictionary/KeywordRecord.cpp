#include "core/dictionary/KeywordRecord.hpp"

#include <fmt/format.h>

#include <atomic>
#include <map>
#include <mutex>

#include "core/Strings.hpp"

namespace isph {

namespace {

struct Record {
  std::string fallback;  // "" when none was given (required, or optional without a default)
  bool hasDefault = false;
  std::string choices;
  std::string range;
};

std::atomic<bool> on{false};
std::mutex mutex;
std::map<std::pair<std::string, std::string>, Record>& records() {
  static std::map<std::pair<std::string, std::string>, Record> r;
  return r;
}

Record& at(std::string_view dictionary, std::string_view key) {
  return records()[{std::string(dictionary), std::string(key)}];
}

}  // namespace

void enableKeywordRecord() { on = true; }
bool keywordRecordOn() { return on.load(std::memory_order_relaxed); }

void recordKeyword(std::string_view dictionary, std::string_view key) {
  if (!keywordRecordOn()) return;
  const std::lock_guard lock(mutex);
  at(dictionary, key);
}

void recordDefault(std::string_view dictionary, std::string_view key, const std::string& fallback) {
  if (!keywordRecordOn()) return;
  const std::lock_guard lock(mutex);
  Record& r = at(dictionary, key);
  r.fallback = fallback;
  r.hasDefault = true;
}

void recordChoices(std::string_view dictionary, std::string_view key, const std::vector<std::string>& choices) {
  if (!keywordRecordOn()) return;
  const std::lock_guard lock(mutex);
  at(dictionary, key).choices = join(choices, " \\| ");
}

void recordRange(std::string_view dictionary, std::string_view key, double lo, double hi) {
  if (!keywordRecordOn()) return;
  const std::lock_guard lock(mutex);
  at(dictionary, key).range = fmt::format("[{}, {}]", lo, hi);
}

std::string keywordReference() {
  const std::lock_guard lock(mutex);
  // The case's dictionaries only (not the headers of field files), named from the case.
  std::map<std::pair<std::string, std::string>, Record> rows;
  for (const auto& [name, r] : records()) {
    std::string dictionary = name.first;
    std::size_t at = std::string::npos;
    for (const char* folder : {"system/", "constant/"}) {
      const std::size_t found = dictionary.rfind(folder);
      if (found != std::string::npos && (found == 0 || dictionary[found - 1] == '/')) at = found;
    }
    if (at == std::string::npos) continue;
    Record& row = rows[{dictionary.substr(at), name.second}];
    if (r.hasDefault) {
      row.hasDefault = true;
      row.fallback = r.fallback;
    }
    if (!r.choices.empty()) row.choices = r.choices;
    if (!r.range.empty()) row.range = r.range;
  }
  std::string out = "| entry | default | choices or range |\n|---|---|---|\n";
  for (const auto& [name, r] : rows) {
    const std::string fallback = r.hasDefault ? (r.fallback.empty() ? "(empty)" : "`" + r.fallback + "`") : "";
    out += fmt::format("| `{}/{}` | {} | {} |\n", name.first, name.second, fallback,
                       r.choices.empty() ? r.range : r.choices);
  }
  return out;
}

}  // namespace isph
