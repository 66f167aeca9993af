#pragma once
// MPI and hypre lifetime for an application or a test main (hypre needs MPI_Init before
// any solver is created, and HYPRE_Init before its first call):
//
//   int main(int argc, char* argv[]) {
//     isph::ParallelEnvironment parallel(argc, argv);
//     return isph::runApplication(spec, argc, argv, body);
//   }
//
// RAII and idempotent: only the instance that initialised MPI (or hypre) finalises it, so
// a second instance, or one created after someone else's MPI_Init, is harmless. It also tells
// the core which rank this is (ParallelRun.hpp: the log is rank 0's, an error ends every rank).
namespace isph {

class ParallelEnvironment {
 public:
  ParallelEnvironment(int& argc, char**& argv);
  ~ParallelEnvironment();
  ParallelEnvironment(const ParallelEnvironment&) = delete;
  ParallelEnvironment& operator=(const ParallelEnvironment&) = delete;

  // Whether MPI is initialised and not yet finalised.
  static bool active();
  // Number of ranks in MPI_COMM_WORLD (1 when MPI is not active).
  static int nProcs();
  // This rank (0 when MPI is not active).
  static int rank();

 private:
  bool ownsMpi_ = false;
  bool ownsHypre_ = false;
};

}  // namespace isph
