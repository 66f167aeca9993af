#include "linearSolvers/hypre/BoomerAMG.hpp"

#include <fmt/format.h>

#include <map>
#include <utility>
#include <vector>

#include "core/Error.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "linearSolvers/hypre/HypreError.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

namespace {

// A word from `codes`, default `fallback` (echoed), as hypre's integer code.
int codeOf(const Dictionary& dict, const char* key, const std::map<std::string, int>& codes,
           const std::string& fallback) {
  std::vector<std::string> names;
  for (const auto& [name, code] : codes) names.push_back(name);
  return codes.at(dict.getChoiceOrDefault(key, names, fallback));
}

void checkRange(const Dictionary& dict, const char* key, bool ok, const std::string& what) {
  if (ok) return;
  const Entry* e = dict.findEntry(key);
  fatalIOError(e ? e->location() : dict.location(), fmt::format("{} must be {}", key, what));
}

// The Krylov setup calls this instead of HYPRE_BoomerAMGSetup while a hierarchy is reused.
HYPRE_Int keepHierarchy(HYPRE_Solver, HYPRE_ParCSRMatrix, HYPRE_ParVector, HYPRE_ParVector) {
  return 0;
}

}  // namespace

BoomerAMGControls BoomerAMGControls::read(const Dictionary& dict) {
  BoomerAMGControls c;
  c.strongThreshold = dict.getOrDefault("strongThreshold", c.strongThreshold);
  checkRange(dict, "strongThreshold", c.strongThreshold > 0.0 && c.strongThreshold < 1.0,
             "between 0 and 1 (0.25 in 2D; 0.5 is worth testing)");
  c.coarsenType = codeOf(dict, "coarsenType", {{"HMIS", 10}, {"PMIS", 8}, {"Falgout", 6}}, "HMIS");
  c.interpType = codeOf(dict, "interpType",
                        {{"extPI", 6},
                         {"ext", 14},
                         {"standard", 8},
                         {"classical", 0},
                         {"direct", 3},
                         {"multipass", 4}},
                        "extPI");
  c.pMaxElmts = dict.getOrDefault("pMaxElmts", c.pMaxElmts);
  checkRange(dict, "pMaxElmts", c.pMaxElmts >= 0, "0 (no truncation) or more");
  c.aggNumLevels = dict.getOrDefault("aggNumLevels", c.aggNumLevels);
  checkRange(dict, "aggNumLevels", c.aggNumLevels >= 0, "0 or more");
  c.reuseSetup = dict.getOrDefault("reuseSetup", c.reuseSetup);
  checkRange(dict, "reuseSetup", c.reuseSetup >= 1, "1 (rebuild every solve) or more");
  c.relaxType = codeOf(dict, "smoother",
                       {{"l1GaussSeidel", -1}, {"GaussSeidel", 3}, {"symmetricGaussSeidel", 6}, {"l1Jacobi", 18}},
                       c.reuseSetup > 1 ? "GaussSeidel" : "l1GaussSeidel");
  if (c.reuseSetup > 1 && (c.relaxType == -1 || c.relaxType == 18)) {
    warning(fmt::format("reuseSetup {} with an l1 smoother: its row norms are those of the matrix the "
                        "hierarchy was built for, and PCG can break down where the matrix changes much "
                        "between solves (smoother GaussSeidel or symmetricGaussSeidel is safe)",
                        c.reuseSetup),
            dict.findEntry("smoother")->location());
  }
  return c;
}

BoomerAMG::~BoomerAMG() { destroy(); }

void BoomerAMG::create() {
  hypreCheck(HYPRE_BoomerAMGCreate(&amg_), "HYPRE_BoomerAMGCreate");
  HYPRE_BoomerAMGSetMaxIter(amg_, 1);  // one V-cycle per application
  HYPRE_BoomerAMGSetTol(amg_, 0.0);
  HYPRE_BoomerAMGSetPrintLevel(amg_, 0);
  HYPRE_BoomerAMGSetCoarsenType(amg_, controls_.coarsenType);
  HYPRE_BoomerAMGSetInterpType(amg_, controls_.interpType);
  HYPRE_BoomerAMGSetPMaxElmts(amg_, controls_.pMaxElmts);
  HYPRE_BoomerAMGSetStrongThreshold(amg_, controls_.strongThreshold);
  HYPRE_BoomerAMGSetAggNumLevels(amg_, controls_.aggNumLevels);
  if (controls_.relaxType == 3) {  // forward sweeps down, backward up: a symmetric V-cycle
    HYPRE_BoomerAMGSetCycleRelaxType(amg_, 3, 1);
    HYPRE_BoomerAMGSetCycleRelaxType(amg_, 4, 2);
  } else if (controls_.relaxType >= 0) {
    HYPRE_BoomerAMGSetRelaxType(amg_, controls_.relaxType);
  }
  hypreCheck(HYPRE_GetError(), "configuring BoomerAMG");
}

void BoomerAMG::destroy() {
  if (amg_) HYPRE_BoomerAMGDestroy(amg_);
  amg_ = nullptr;
}

HYPRE_PtrToParSolverFcn BoomerAMG::prepare(long firstRow, long nRows) {
  // (The same decision on every rank of a parallel run: the set-up is collective.)
  const bool sameMatrixShape = allRanks(amg_ && firstRow == firstRow_ && nRows == nRows_);
  const bool keep = std::exchange(keepNext_, false);
  const bool renumbered = std::exchange(rebuildNext_, false);
  const bool degraded = std::exchange(degraded_, false);
  if (sameMatrixShape && !renumbered && (keep || (!degraded && solvesWithHierarchy_ < controls_.reuseSetup))) {
    ++solvesWithHierarchy_;
    lastReused_ = true;
    return keepHierarchy;
  }
  destroy();
  create();
  firstRow_ = firstRow;
  nRows_ = nRows;
  solvesWithHierarchy_ = 1;
  firstIterations_ = -1;
  ++built_;
  lastReused_ = false;
  return HYPRE_BoomerAMGSetup;
}

void BoomerAMG::solved(int iterations) {
  if (firstIterations_ < 0) {
    firstIterations_ = iterations;
  } else if (2 * iterations > 3 * firstIterations_ + 4) {
    degraded_ = true;
  }
}

}  // namespace isph
