#include "core/ParallelRun.hpp"

namespace isph {

namespace {
ParallelRun current;
}

const ParallelRun& parallelRun() { return current; }

void setParallelRun(const ParallelRun& run) { current = run; }

}  // namespace isph
