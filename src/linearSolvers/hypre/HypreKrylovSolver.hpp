#pragma once
// hypre's Krylov solvers on ParCSR matrices, registered as `PCG` (symmetric systems; two-norm
// criterion ||r|| / ||b||, residual recomputed at the end), `GMRES` (kDim 30) and `BiCGSTAB`,
// each with `preconditioner BoomerAMG` (default, see BoomerAMG.hpp), `diagonal` (Jacobi)
// or `none`. The system goes through the IJ interface on every solve (HypreSystem.hpp).
#include <memory>
#include <string>

#include "linearSolvers/ControlledLinearSolver.hpp"
#include "linearSolvers/hypre/BoomerAMG.hpp"

namespace isph {

class HypreKrylovSolver : public ControlledLinearSolver {
 public:
  enum class Method { PCG, GMRES, BiCGSTAB };
  enum class Preconditioner { BoomerAMG, diagonal, none };

  HypreKrylovSolver(Method method, const Dictionary& dict, const LinearSolverControls& controls);
  ~HypreKrylovSolver() override;

  std::string name() const override;  // "BoomerAMG-PCG", "diagonal-GMRES", "BiCGSTAB"
  void keepPreconditionerForNextSolve() override {
    if (amg_) amg_->keepForNextSolve();
  }
  void rebuildPreconditionerForNextSolve() override {
    if (amg_) amg_->rebuildForNextSolve();
  }
  int preconditionersBuilt() const override { return amg_ ? amg_->hierarchiesBuilt() : 0; }
  // The BoomerAMG preconditioner (nullptr unless chosen): hierarchies built, reuse.
  const BoomerAMG* amg() const { return amg_.get(); }

 protected:
  int iterate(const SparseSystem& A, std::vector<double>& x, double target, int maxIter,
              SolverPerformance& performance) override;

 private:
  Method method_;
  Preconditioner preconditioner_;
  int kDim_ = 30;  // GMRES restart
  std::unique_ptr<BoomerAMG> amg_;
  bool warnedSymmetry_ = false;
};

}  // namespace isph
