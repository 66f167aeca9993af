#pragma once
// What the dictionary parser refuses, with a FatalError naming the file, the line and the
// limit: input that no case needs and that would otherwise crash (a stack overflow), exhaust
// the memory or never end (#include "/dev/zero").
#include <cstddef>

namespace isph {

struct DictionaryLimits {
  static constexpr int maxNesting = 100;  // sub-dictionaries, and ( [ { inside one value
  static constexpr std::size_t maxFileBytes = std::size_t{256} << 20;  // each file (#include too)
  static constexpr std::size_t maxTotalBytes = std::size_t{1} << 30;   // a file and its #includes
  static constexpr std::size_t maxTokenBytes = std::size_t{1} << 20;   // one word or string
  // Entries and tokens copied by $ substitution in one parse: each `$a` copies what a names,
  // so that a chain `b $a $a; c $b $b; ...` doubles at every step.
  static constexpr std::size_t maxSubstituted = std::size_t{1} << 22;
  // Elements of one list value: a uniform list N{v} costs N copies for a few bytes of text.
  static constexpr std::size_t maxListElements = std::size_t{1} << 24;
};

}  // namespace isph
