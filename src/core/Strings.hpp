#pragma once
// Small string helpers: edit distance for "did you mean" hints, joining, trimming.
#include <string>
#include <string_view>
#include <vector>

namespace isph {

// Levenshtein distance between two words.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidate closest to `word`, or "" when none is close enough to be a likely typo.
std::string nearestWord(std::string_view word, const std::vector<std::string>& candidates);

// The candidate closest to `word` within `maxEdits` edits (a one-letter word: a case-only
// difference, a two-letter one: one edit), or "" when none is.
std::string nearestWithin(std::string_view word, const std::vector<std::string>& candidates, std::size_t maxEdits);

// " (did you mean X?)" or "" when nothing is close.
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates);

std::string join(const std::vector<std::string>& items, std::string_view separator);

std::string_view trim(std::string_view s);

}  // namespace isph
