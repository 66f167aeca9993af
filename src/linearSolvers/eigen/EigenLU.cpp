// Eigen's SparseLU (COLAMD ordering), registered as `EigenLU`: the exact reference for tests
// and small systems. Each pass is one step of iterative refinement from the warm start,
// x += LU^-1 (b - A x), so it reports 1 iteration (more if refinement was needed).
#include <fmt/format.h>

#include <Eigen/SparseLU>
#include <chrono>

#include "linearSolvers/ControlledLinearSolver.hpp"
#include "linearSolvers/eigen/EigenMatrix.hpp"

namespace isph {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class EigenLU : public ControlledLinearSolver {
 public:
  using ControlledLinearSolver::ControlledLinearSolver;
  std::string name() const override { return "Eigen-LU"; }

 protected:
  int iterate(const SparseSystem& A, std::vector<double>& x, double, int,
              SolverPerformance& performance) override {
    auto start = std::chrono::steady_clock::now();
    const Eigen::SparseMatrix<double> M = toEigen(A);  // SparseLU wants column-major
    performance.assemblySeconds += secondsSince(start);

    start = std::chrono::steady_clock::now();
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
    lu.compute(M);
    performance.setupSeconds += secondsSince(start);
    if (lu.info() != Eigen::Success) {
      warning(fmt::format("{}: factorisation failed for {} ({})", name(), controls().field,
                          lu.lastErrorMessage()));
      return 0;
    }

    start = std::chrono::steady_clock::now();
    const Eigen::VectorXd residual = asEigen(A.rhs) - M * asEigen(x);
    asEigen(x) += lu.solve(residual);
    performance.solveSeconds += secondsSince(start);
    return 1;
  }
};

const bool registered = LinearSolverRegistry::add(
    "EigenLU",
    [](const Dictionary&, const LinearSolverControls& c) -> std::unique_ptr<LinearSolver> {
      return std::make_unique<EigenLU>(c);
    });

}  // namespace

}  // namespace isph
