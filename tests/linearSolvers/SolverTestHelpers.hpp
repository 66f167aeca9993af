#pragma once
// Helpers for the linear-solver tests: solvers from dictionary text (as if read from
// system/isphSolution) and the exact reference solution by Eigen's SparseLU.
#include <memory>
#include <string>
#include <vector>

#include "core/dictionary/Dictionary.hpp"
#include "linearSolvers/LinearSolver.hpp"

namespace isph::test {

// The solver of `p { <entries> }` parsed from a file named system/isphSolution.
inline std::unique_ptr<LinearSolver> solverFrom(const std::string& entries) {
  const Dictionary dict = Dictionary::parse("p\n{\n" + entries + "\n}\n", "system/isphSolution");
  return makeLinearSolver(dict.subDict("p"), "p");
}

inline std::vector<double> exactSolution(const SparseSystem& A) {
  std::vector<double> x;
  const SolverPerformance perf = solverFrom("solver EigenLU; tolerance 1e-12;")->solve(A, x);
  if (!perf.converged)
    throw std::runtime_error("EigenLU reference did not converge: " + perf.str());
  return x;
}

// ||x - y|| / ||y||
inline double relativeDifference(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> d(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) d[i] = x[i] - y[i];
  return norm2(d) / norm2(y);
}

}  // namespace isph::test
