#pragma once
// Contiguous global numbers for the rows of a distributed linear system: hypre's ParCSR
// matrices want each rank's rows as one block, so rank r numbers its n_r rows (its own
// material particles, in their local order) from first_r = n_0 + ... + n_(r-1). A ghost
// particle's row is its owner's number, sent with it (Halo::exchange).
namespace isph {

struct GlobalNumbering {
  long first = 0;    // this rank's first row
  long nLocal = 0;   // this rank's rows
  long nGlobal = 0;  // all ranks' rows

  // Collective: every rank gives its own count.
  static GlobalNumbering of(long nLocal);
  long row(long localIndex) const { return first + localIndex; }
  bool owns(long row) const { return row >= first && row < first + nLocal; }
};

}  // namespace isph
