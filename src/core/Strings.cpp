#include "core/Strings.hpp"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace isph {

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      // A case-only difference costs little: "endtime" is surely "endTime".
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : (same ? 0 : 1));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string nearestWord(std::string_view word, const std::vector<std::string>& candidates) {
  // No keyword is this long: no typo of one (and the edit distance costs length squared).
  if (word.size() > 256) return {};
  std::string best;
  std::size_t bestDistance = std::string::npos;
  for (const auto& candidate : candidates) {
    // Lengths that differ by more than 3 are more than 3 edits apart (the most accepted below).
    if (candidate.size() > word.size() + 3 || word.size() > candidate.size() + 3) continue;
    const std::size_t d = editDistance(word, candidate);
    if (d < bestDistance) {
      bestDistance = d;
      best = candidate;
    }
  }
  // Accept up to a third of the word's length in edits (at least 1, at most 3).
  // A one-letter word only matches case-insensitively ("q" is not a typo of "a").
  const std::size_t limit = word.size() < 2 ? 0 : std::clamp<std::size_t>(word.size() / 3, 1, 3);
  if (best.empty() || bestDistance > limit) return {};
  return best;
}

std::string nearestWithin(std::string_view word, const std::vector<std::string>& candidates, std::size_t maxEdits) {
  if (word.empty() || word.size() > 256) return {};
  const std::size_t limit = std::min(maxEdits, word.size() - 1);
  std::string best;
  std::size_t bestDistance = limit + 1;
  for (const auto& candidate : candidates) {
    if (candidate.size() > word.size() + limit || word.size() > candidate.size() + limit) continue;
    const std::size_t d = editDistance(word, candidate);
    if (d < bestDistance) {
      bestDistance = d;
      best = candidate;
    }
  }
  return best;
}

std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string nearest = nearestWord(word, candidates);
  return nearest.empty() ? std::string{} : " (did you mean " + nearest + "?)";
}

std::string join(const std::vector<std::string>& items, std::string_view separator) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i) out += separator;
    out += items[i];
  }
  return out;
}

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

}  // namespace isph
