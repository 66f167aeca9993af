#include "core/app/DefaultThreads.hpp"

#include <cstdlib>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace isph {

void applyDefaultThreadCount() {
#ifdef _OPENMP
  const char* given = std::getenv("OMP_NUM_THREADS");
  if (!given || !*given) omp_set_num_threads(1);
#endif
}

}  // namespace isph
