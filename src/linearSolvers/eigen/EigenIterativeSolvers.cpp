// Eigen's iterative solvers, the fallbacks of numerics.md §5 (no MPI needed), registered as
//   EigenCG         conjugate gradients, IncompleteCholesky, Lower|Upper on a row-major matrix
//                   (symmetric positive definite systems);
//   EigenBiCGSTAB   BiCGSTAB with IncompleteLUT (`droptol 1e-4; fillFactor 10;`).
// Eigen's stopping test is ||r|| <= tolerance * ||b||, the same residual as ours.
#include <fmt/format.h>

#include <Eigen/IterativeLinearSolvers>
#include <chrono>

#include "core/dictionary/Dictionary.hpp"
#include "linearSolvers/ControlledLinearSolver.hpp"
#include "linearSolvers/eigen/EigenMatrix.hpp"

namespace isph {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Runs any Eigen iterative solver: convert, compute the preconditioner, iterate from x.
template <class EigenSolver>
int runEigen(EigenSolver& solver, const std::string& name, const SparseSystem& A,
             std::vector<double>& x, double target, int maxIter, SolverPerformance& performance) {
  auto start = std::chrono::steady_clock::now();
  const EigenRowMatrix M = toEigen(A);
  performance.assemblySeconds += secondsSince(start);

  start = std::chrono::steady_clock::now();
  solver.setTolerance(target);
  solver.setMaxIterations(maxIter);
  solver.compute(M);
  performance.setupSeconds += secondsSince(start);
  if (solver.preconditioner().info() != Eigen::Success) {
    warning(fmt::format("{}: the preconditioner could not be computed", name));
    return 0;
  }

  start = std::chrono::steady_clock::now();
  const Eigen::VectorXd guess = asEigen(x);
  asEigen(x) = solver.solveWithGuess(asEigen(A.rhs), guess);
  performance.solveSeconds += secondsSince(start);
  return static_cast<int>(solver.iterations());
}

class EigenCG : public ControlledLinearSolver {
 public:
  using ControlledLinearSolver::ControlledLinearSolver;
  std::string name() const override { return "Eigen-CG"; }

 protected:
  int iterate(const SparseSystem& A, std::vector<double>& x, double target, int maxIter,
              SolverPerformance& performance) override {
    Eigen::ConjugateGradient<EigenRowMatrix, Eigen::Lower | Eigen::Upper,
                             Eigen::IncompleteCholesky<double>>
        cg;
    return runEigen(cg, name(), A, x, target, maxIter, performance);
  }
};

class EigenBiCGSTAB : public ControlledLinearSolver {
 public:
  EigenBiCGSTAB(const Dictionary& dict, const LinearSolverControls& controls)
      : ControlledLinearSolver(controls),
        droptol_(dict.getOrDefault("droptol", 1e-4)),
        fillFactor_(dict.getOrDefault("fillFactor", 10)) {
    if (!(droptol_ >= 0.0)) {
      fatalIOError(dict.findEntry("droptol")->location(), "droptol must not be negative");
    }
    if (fillFactor_ < 1) {
      fatalIOError(dict.findEntry("fillFactor")->location(), "fillFactor must be at least 1");
    }
  }
  std::string name() const override { return "Eigen-BiCGSTAB"; }

 protected:
  int iterate(const SparseSystem& A, std::vector<double>& x, double target, int maxIter,
              SolverPerformance& performance) override {
    Eigen::BiCGSTAB<EigenRowMatrix, Eigen::IncompleteLUT<double>> bicgstab;
    bicgstab.preconditioner().setDroptol(droptol_);
    bicgstab.preconditioner().setFillfactor(fillFactor_);
    return runEigen(bicgstab, name(), A, x, target, maxIter, performance);
  }

 private:
  double droptol_;
  int fillFactor_;
};

const bool registered =
    LinearSolverRegistry::add(
        "EigenCG",
        [](const Dictionary&, const LinearSolverControls& c) -> std::unique_ptr<LinearSolver> {
          return std::make_unique<EigenCG>(c);
        }) &&
    LinearSolverRegistry::add(
        "EigenBiCGSTAB",
        [](const Dictionary& d, const LinearSolverControls& c) -> std::unique_ptr<LinearSolver> {
          return std::make_unique<EigenBiCGSTAB>(d, c);
        });

}  // namespace

}  // namespace isph
