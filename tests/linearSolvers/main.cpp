// GoogleTest main for the linear-solver tests: hypre needs MPI (and HYPRE_Init) for the
// whole run, so the ParallelEnvironment outlives every test.
#include <gtest/gtest.h>

#include "linearSolvers/ParallelEnvironment.hpp"

int main(int argc, char** argv) {
  const isph::ParallelEnvironment parallel(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
