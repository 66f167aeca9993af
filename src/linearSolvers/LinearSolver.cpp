#include "linearSolvers/LinearSolver.hpp"

#include <fmt/format.h>

#include "core/dictionary/Dictionary.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

namespace {

SourceLocation locationOf(const Dictionary& dict, std::string_view key) {
  const Entry* e = dict.findEntry(key);
  return e ? e->location() : dict.location();
}

}  // namespace

LinearSolver::~LinearSolver() = default;

LinearSolverControls LinearSolverControls::read(const Dictionary& dict, const std::string& field) {
  LinearSolverControls c;
  c.field = field;
  c.tolerance = dict.getOrDefault("tolerance", c.tolerance);
  c.relTol = dict.getOrDefault("relTol", c.relTol);
  c.maxIter = dict.getOrDefault("maxIter", c.maxIter);
  if (!(c.tolerance >= 0.0)) {
    fatalIOError(locationOf(dict, "tolerance"),
                 fmt::format("tolerance {} must not be negative", c.tolerance));
  }
  if (!(c.relTol >= 0.0 && c.relTol < 1.0)) {
    fatalIOError(locationOf(dict, "relTol"), fmt::format("relTol {} must lie in [0, 1)", c.relTol));
  }
  if (c.maxIter < 1) {
    fatalIOError(locationOf(dict, "maxIter"),
                 fmt::format("maxIter {} must be at least 1", c.maxIter));
  }
  return c;
}

std::unique_ptr<LinearSolver> makeLinearSolver(const Dictionary& solverDict,
                                               const std::string& field) {
  const LinearSolverControls controls = LinearSolverControls::read(solverDict, field);
  const std::string name = solverDict.getOrDefault<std::string>("solver", "PCG");
  auto solver = LinearSolverRegistry::create(
      name, "linear solver", locationOf(solverDict, "solver"), solverDict, controls);
  solverDict.checkKeywords();
  if (distributedRun() && !solver->distributed()) {
    fatalIOError(locationOf(solverDict, "solver"),
                 fmt::format("the {} solver runs on one rank; a parallel run ({} ranks) needs a hypre solver "
                             "(PCG, GMRES or BiCGSTAB) for {}",
                             solver->name(), nRanks(), field));
  }
  return solver;
}

std::vector<std::string> linearSolverNames() { return LinearSolverRegistry::names(); }

}  // namespace isph
