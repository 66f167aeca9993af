#pragma once
// A dictionary value outside its valid range is an error at its entry (or at the dictionary,
// for a default): "keyword 'eta' in laplacian: 2 is outside the valid range [1e-06, 1]".
#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {

inline void requireRange(const Dictionary& d, const char* key, double value, double lo, double hi) {
  recordRange(d.name(), key, lo, hi);
  if (value < lo || value > hi) {
    const Entry* e = d.findEntry(key);
    fatalIOError(e ? e->location() : d.location(),
                 fmt::format("keyword '{}' in {}: {} is outside the valid range [{}, {}]", key, d.name(), value, lo, hi));
  }
}

}  // namespace isph
