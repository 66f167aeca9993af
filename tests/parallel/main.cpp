// GoogleTest main for the parallel layer's tests, run by ctest under mpirun on 1 and 3 ranks
// (tests/parallel/CMakeLists.txt): MPI and hypre live for the whole run (ParallelEnvironment),
// rank 0 prints the usual report, the other ranks only their failures, and a failure on any
// rank fails the run (its exit status).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "linearSolvers/ParallelEnvironment.hpp"

namespace {

class FailuresOnly : public ::testing::EmptyTestEventListener {
 public:
  explicit FailuresOnly(int rank) : rank_(rank) {}
  void OnTestStart(const ::testing::TestInfo& test) override {
    test_ = std::string(test.test_suite_name()) + "." + test.name();
  }
  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (!result.failed()) return;
    std::fprintf(stderr, "[rank %d] %s failed at %s:%d\n%s\n", rank_, test_.c_str(),
                 result.file_name() ? result.file_name() : "?", result.line_number(), result.message());
  }

 private:
  int rank_;
  std::string test_;
};

}  // namespace

int main(int argc, char** argv) {
  const isph::ParallelEnvironment parallel(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (const int rank = isph::ParallelEnvironment::rank(); rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new FailuresOnly(rank));
  }
  return RUN_ALL_TESTS();
}
