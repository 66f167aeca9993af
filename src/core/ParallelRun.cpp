#include "core/ParallelRun.hpp"

namespace isph {

namespace {
ParallelRun current;
}

const ParallelRun& parallelRun() { return current; }

void setParallelRun(const ParallelRun& run) { current = run; }

int agreeOverRanks(int value) { return current.nProcs > 1 && current.maxOverRanks ? current.maxOverRanks(value) : value; }

double agreeOnMinimum(double value) {
  return current.nProcs > 1 && current.minOverRanks ? current.minOverRanks(value) : value;
}

}  // namespace isph
