#pragma once
// Resizing a buffer that every step refills (a neighbour list, a matrix's columns and values):
// std::vector::resize past the capacity allocates the old size plus the larger of the old size
// and the growth (libstdc++), so a list that grows by one pair holds twice its memory from then
// on; at 160k particles that was half of the dam break's neighbour list (doc/notes/scaling.md).
// Here the old buffer is freed first (its contents are about to be overwritten, so none are
// kept) and n plus 1/32 is allocated, room for the next steps' small growth.
#include <cstddef>
#include <vector>

namespace isph {

template <class T>
void resizeForOverwrite(std::vector<T>& v, std::size_t n) {
  if (n > v.capacity()) {
    std::vector<T>().swap(v);
    v.reserve(n + n / 32);
  }
  v.resize(n);
}

}  // namespace isph
