#include "parallel/GlobalNumbering.hpp"

#include "parallel/Reduce.hpp"

namespace isph {

GlobalNumbering GlobalNumbering::of(long nLocal) {
  return {.first = sumOverLowerRanks(nLocal), .nLocal = nLocal, .nGlobal = sumOverRanks(nLocal)};
}

}  // namespace isph
