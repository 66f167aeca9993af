#pragma once
// hypre's BoomerAMG as a preconditioner (one V(1,1) cycle: MaxIter 1, Tol 0), with the
// settings of numerics.md §5, each optional in the solver dictionary (defaults echoed):
//
//   strongThreshold 0.25;            // 0.5 is worth testing for wide SPH stencils
//   coarsenType     HMIS;            // HMIS (10) | PMIS (8, the GPU path) | Falgout (6)
//   interpType      extPI;           // extPI (ext+i, 6) | ext (14) | standard (8) | classical (0)
//                                    //   | direct (3) | multipass (4)
//   pMaxElmts       4;               // interpolation truncation
//   aggNumLevels    0;               // 1 above ~1e5 unknowns
//   smoother        l1GaussSeidel;   // l1GaussSeidel (13 down, 14 up: symmetric V-cycle)
//                                    //   | GaussSeidel (3 down, 4 up) | symmetricGaussSeidel
//                                    //   (6: both sweeps each time, about 1.6 × the cost of
//                                    //   a V-cycle) | l1Jacobi (18, GPU);
//                                    //   default GaussSeidel when reuseSetup > 1
//   reuseSetup      1;               // keep a hierarchy for N solves (N - 1 reuses)
//
// Reuse: the hierarchy built for one matrix preconditions the next reuseSetup - 1 solves
// (the finest-level smoother works on the current matrix; the coarse levels are the old
// ones), unless a solve with it takes more than 1.5 × + 2 the Krylov iterations of its first
// (the matrix has drifted: a soil column that starts to yield, whose η falls by decades in a
// few steps, took 19 iterations per solve with a kept hierarchy against 12.5 with fresh
// ones, 160k particles over the first 10 steps). A matrix of another size, or renumbered
// unknowns (rebuildForNextSolve()), forces a rebuild. keepForNextSolve() asks the same for the next solve alone, whatever reuseSetup
// says (the caller knows its next matrix is a small change of the last: a fixed-point pass).
// The l1 smoothers divide by the row norms of the matrix they were set up for: where the
// matrix changes much between solves (the velocity system of a yielding soil, whose η falls
// by decades where it starts to flow), a stale norm over-relaxes and PCG breaks down
// (measured: the column collapse at 2 mm, at the second step). Gauss-Seidel uses the
// current matrix's diagonal, so with reuseSetup > 1 it is the default, and an l1 smoother
// given explicitly draws a warning.
#include <HYPRE_parcsr_ls.h>

#include <string>

namespace isph {

class Dictionary;

struct BoomerAMGControls {
  double strongThreshold = 0.25;
  int coarsenType = 10;  // HMIS
  int interpType = 6;    // ext+i
  int pMaxElmts = 4;
  int aggNumLevels = 0;
  int relaxType = -1;  // -1: hypre's default (l1-GS forward down, backward up); 3: GS 3 down, 4 up
  int reuseSetup = 1;

  // FatalError at the keyword's line for an unknown name or an out-of-range value.
  static BoomerAMGControls read(const Dictionary& dict);
};

class BoomerAMG {
 public:
  explicit BoomerAMG(const BoomerAMGControls& controls) : controls_(controls) {}
  ~BoomerAMG();
  BoomerAMG(const BoomerAMG&) = delete;
  BoomerAMG& operator=(const BoomerAMG&) = delete;

  // Call before the Krylov setup for a matrix of global rows [firstRow, firstRow + nRows):
  // returns the preconditioner-setup function to hand to the Krylov solver, either
  // HYPRE_BoomerAMGSetup on a fresh hierarchy or a no-op that keeps the current one.
  HYPRE_PtrToParSolverFcn prepare(long firstRow, long nRows);
  void keepForNextSolve() { keepNext_ = true; }
  // The Krylov iterations of the solve just done with the current hierarchy: a kept
  // hierarchy that has become a poor preconditioner (more than 1.5 × + 2 the iterations of
  // its first solve) is rebuilt for the next solve although reuses are left.
  void solved(int iterations);
  void rebuildForNextSolve() { rebuildNext_ = true; }  // the unknowns were renumbered

  HYPRE_Solver handle() const { return amg_; }
  static HYPRE_PtrToParSolverFcn solveFunction() { return HYPRE_BoomerAMGSolve; }

  int hierarchiesBuilt() const { return built_; }  // for tests and diagnostics
  bool lastReused() const { return lastReused_; }

 private:
  void create();
  void destroy();

  BoomerAMGControls controls_;
  HYPRE_Solver amg_ = nullptr;
  long firstRow_ = -1, nRows_ = -1;  // the matrix the hierarchy was built for
  int solvesWithHierarchy_ = 0;
  int firstIterations_ = -1;  // of the hierarchy's first solve
  bool degraded_ = false;
  int built_ = 0;
  bool lastReused_ = false;
  bool keepNext_ = false;
  bool rebuildNext_ = false;
};

}  // namespace isph
