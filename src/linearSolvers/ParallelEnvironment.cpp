#include "linearSolvers/ParallelEnvironment.hpp"

#include <HYPRE_utilities.h>
#include <mpi.h>

#include "core/Error.hpp"
#include "core/ParallelRun.hpp"

namespace isph {

namespace {
bool hypreInitialised = false;

void abortAllRanks(int status) { MPI_Abort(MPI_COMM_WORLD, status); }

int maxOverAllRanks(int value) {
  int out = value;
  MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return out;
}
double minOverAllRanks(double value) {
  double out = value;
  MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  return out;
}
}  // namespace

ParallelEnvironment::ParallelEnvironment(int& argc, char**& argv) {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (finalised)
      fatalError("ParallelEnvironment: MPI was already finalised and cannot be started again");
    if (MPI_Init(&argc, &argv) != MPI_SUCCESS) fatalError("ParallelEnvironment: MPI_Init failed");
    ownsMpi_ = true;
  }
  setParallelRun({.rank = rank(), .nProcs = nProcs(), .abort = abortAllRanks, .maxOverRanks = maxOverAllRanks,
                  .minOverRanks = minOverAllRanks});
  if (!hypreInitialised) {
    HYPRE_Init();
    hypreInitialised = true;
    ownsHypre_ = true;
  }
}

ParallelEnvironment::~ParallelEnvironment() {
  if (ownsHypre_) {
    HYPRE_Finalize();
    hypreInitialised = false;
  }
  if (ownsMpi_ && active()) {
    MPI_Finalize();
    setParallelRun({});
  }
}

bool ParallelEnvironment::active() {
  int initialised = 0;
  int finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}

int ParallelEnvironment::nProcs() {
  if (!active()) return 1;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

int ParallelEnvironment::rank() {
  if (!active()) return 0;
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

}  // namespace isph
