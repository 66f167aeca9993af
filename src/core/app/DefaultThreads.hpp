#pragma once
// The OpenMP threads of an application when OMP_NUM_THREADS is not set: one, not one per core.
// On the 2-core machines the toolkit is measured on, a second thread gains little and costs
// much when the other core is busy (hypre's solves, most of a step, are serial in Debian's
// build): the barrier's -test took 29 s on one thread, 30.6 s on two (54 s of CPU), and 221 s
// on two beside another job (issue 53); tutorials/benchmarks/scaling's 10k column collapse
// 0.87 s on one, 0.94 s on two (doc/notes/scaling.md). A large scene on an idle machine gains
// 1.1-1.3x from two threads there: set OMP_NUM_THREADS=2, or run on MPI ranks (runSolver does).
namespace isph {

// Sets one OpenMP thread unless OMP_NUM_THREADS is set (then OpenMP's own reading of it holds).
void applyDefaultThreadCount();

}  // namespace isph
