#pragma once
// Which MPI rank this process is, as the core needs to know it without linking MPI: the log
// (Log.hpp) and warnings are written by rank 0 only, the banner names the ranks, and a
// FatalError on one rank of a parallel run ends all of them (the others would wait in their
// next collective call for ever). ParallelEnvironment (linearSolvers) sets it after MPI_Init;
// until then, and in a serial run, this process is rank 0 of 1.
namespace isph {

struct ParallelRun {
  int rank = 0;
  int nProcs = 1;
  void (*abort)(int status) = nullptr;  // ends every rank (MPI_Abort); null in a serial run
  // The largest of an integer over the ranks (MPI_Allreduce, collective): decisions every rank
  // must take alike, such as stopping after a signal or re-reading a changed controlDict.
  // Null without MPI.
  int (*maxOverRanks)(int value) = nullptr;
  // The smallest of a double over the ranks (collective), as maxOverRanks: the latest time that
  // every processor directory holds (Time). Null without MPI.
  double (*minOverRanks)(double value) = nullptr;
};

// max over the ranks of a parallel run; the value itself otherwise.
int agreeOverRanks(int value);
// min over the ranks of a parallel run; the value itself otherwise.
double agreeOnMinimum(double value);

const ParallelRun& parallelRun();
void setParallelRun(const ParallelRun& run);
// Rank 0: the one that writes the log, the function objects' files and the time state.
inline bool isMasterRank() { return parallelRun().rank == 0; }

}  // namespace isph
