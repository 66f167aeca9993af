#pragma once
// The keyword reference of an application, made by its readers themselves: with the record on
// (an application's -listKeywords), every entry a Dictionary is asked for is recorded with
// what the reader says of it: required or its default, its choices, its valid range
// (requireRange). keywordReference() prints them as a Markdown table, so that the reference
// page (doc/keywords.md) is generated from the code and cannot drift from it.
#include <string>
#include <string_view>
#include <vector>

namespace isph {

void enableKeywordRecord();
bool keywordRecordOn();

// `dictionary`: the dictionary's name (its file, and sub-dictionaries after '/').
void recordKeyword(std::string_view dictionary, std::string_view key);
void recordDefault(std::string_view dictionary, std::string_view key, const std::string& fallback);
void recordChoices(std::string_view dictionary, std::string_view key, const std::vector<std::string>& choices);
void recordRange(std::string_view dictionary, std::string_view key, double lo, double hi);

// The table: | entry | default | choices or range |, one row per entry of the case's
// dictionaries (system/..., constant/...), by dictionary then keyword.
std::string keywordReference();

}  // namespace isph
