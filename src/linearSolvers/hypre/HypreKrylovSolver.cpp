#include "linearSolvers/hypre/HypreKrylovSolver.hpp"

#include <HYPRE_krylov.h>
#include <fmt/format.h>

#include <chrono>

#include "core/dictionary/Dictionary.hpp"
#include "linearSolvers/ParallelEnvironment.hpp"
#include "linearSolvers/hypre/HypreError.hpp"
#include "linearSolvers/hypre/HypreSystem.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

namespace {

using ParFcn = HYPRE_Int (*)(HYPRE_Solver, HYPRE_ParCSRMatrix, HYPRE_ParVector, HYPRE_ParVector);

// One hypre Krylov method's entry points (the ParCSR interface of each is alike).
struct KrylovFunctions {
  const char* name;
  HYPRE_Int (*create)(MPI_Comm, HYPRE_Solver*);
  HYPRE_Int (*destroy)(HYPRE_Solver);
  HYPRE_Int (*setTol)(HYPRE_Solver, HYPRE_Real);
  HYPRE_Int (*setMaxIter)(HYPRE_Solver, HYPRE_Int);
  HYPRE_Int (*setPrecond)(HYPRE_Solver, HYPRE_PtrToParSolverFcn, HYPRE_PtrToParSolverFcn,
                          HYPRE_Solver);
  ParFcn setup;
  ParFcn solve;
  HYPRE_Int (*iterations)(HYPRE_Solver, HYPRE_Int*);
};

const KrylovFunctions& functionsOf(HypreKrylovSolver::Method method) {
  static const KrylovFunctions pcg{"PCG",
                                   HYPRE_ParCSRPCGCreate,
                                   HYPRE_ParCSRPCGDestroy,
                                   HYPRE_ParCSRPCGSetTol,
                                   HYPRE_ParCSRPCGSetMaxIter,
                                   HYPRE_ParCSRPCGSetPrecond,
                                   HYPRE_ParCSRPCGSetup,
                                   HYPRE_ParCSRPCGSolve,
                                   HYPRE_ParCSRPCGGetNumIterations};
  static const KrylovFunctions gmres{"GMRES",
                                     HYPRE_ParCSRGMRESCreate,
                                     HYPRE_ParCSRGMRESDestroy,
                                     HYPRE_ParCSRGMRESSetTol,
                                     HYPRE_ParCSRGMRESSetMaxIter,
                                     HYPRE_ParCSRGMRESSetPrecond,
                                     HYPRE_ParCSRGMRESSetup,
                                     HYPRE_ParCSRGMRESSolve,
                                     HYPRE_ParCSRGMRESGetNumIterations};
  static const KrylovFunctions bicgstab{"BiCGSTAB",
                                        HYPRE_ParCSRBiCGSTABCreate,
                                        HYPRE_ParCSRBiCGSTABDestroy,
                                        HYPRE_ParCSRBiCGSTABSetTol,
                                        HYPRE_ParCSRBiCGSTABSetMaxIter,
                                        HYPRE_ParCSRBiCGSTABSetPrecond,
                                        HYPRE_ParCSRBiCGSTABSetup,
                                        HYPRE_ParCSRBiCGSTABSolve,
                                        HYPRE_ParCSRBiCGSTABGetNumIterations};
  switch (method) {
    case HypreKrylovSolver::Method::PCG:
      return pcg;
    case HypreKrylovSolver::Method::GMRES:
      return gmres;
    case HypreKrylovSolver::Method::BiCGSTAB:
      break;
  }
  return bicgstab;
}

// A Krylov solver object, destroyed on scope exit.
class KrylovHandle {
 public:
  explicit KrylovHandle(const KrylovFunctions& f) : f_(f) {
    hypreCheck(f_.create(MPI_COMM_WORLD, &solver_), f_.name);
  }
  ~KrylovHandle() {
    if (solver_) f_.destroy(solver_);
  }
  KrylovHandle(const KrylovHandle&) = delete;
  KrylovHandle& operator=(const KrylovHandle&) = delete;
  HYPRE_Solver get() const { return solver_; }

 private:
  const KrylovFunctions& f_;
  HYPRE_Solver solver_ = nullptr;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void requireMpi(const Dictionary& dict, const std::string& solver) {
  const Entry* e = dict.findEntry("solver");
  const SourceLocation where = e ? e->location() : dict.location();
  if (!ParallelEnvironment::active()) {
    fatalIOError(
        where,
        fmt::format("the hypre solver {} needs MPI: create an isph::ParallelEnvironment at the "
                    "start of main (or choose an Eigen solver)",
                    solver));
  }
}

template <HypreKrylovSolver::Method method>
std::unique_ptr<LinearSolver> makeHypre(const Dictionary& dict,
                                        const LinearSolverControls& controls) {
  return std::make_unique<HypreKrylovSolver>(method, dict, controls);
}

const bool registered =
    LinearSolverRegistry::add("PCG", makeHypre<HypreKrylovSolver::Method::PCG>) &&
    LinearSolverRegistry::add("GMRES", makeHypre<HypreKrylovSolver::Method::GMRES>) &&
    LinearSolverRegistry::add("BiCGSTAB", makeHypre<HypreKrylovSolver::Method::BiCGSTAB>);

}  // namespace

HypreKrylovSolver::HypreKrylovSolver(Method method, const Dictionary& dict,
                                     const LinearSolverControls& controls)
    : ControlledLinearSolver(controls), method_(method) {
  requireMpi(dict, functionsOf(method).name);
  const std::string p =
      dict.getChoiceOrDefault("preconditioner", {"BoomerAMG", "diagonal", "none"}, "BoomerAMG");
  preconditioner_ = p == "BoomerAMG"  ? Preconditioner::BoomerAMG
                    : p == "diagonal" ? Preconditioner::diagonal
                                      : Preconditioner::none;
  if (preconditioner_ == Preconditioner::BoomerAMG) {
    amg_ = std::make_unique<BoomerAMG>(BoomerAMGControls::read(dict));
  }
  if (method_ == Method::GMRES) {
    kDim_ = dict.getOrDefault("kDim", kDim_);
    if (kDim_ < 1) {
      fatalIOError(dict.findEntry("kDim")->location(),
                   "kDim (the GMRES restart) must be at least 1");
    }
  }
}

HypreKrylovSolver::~HypreKrylovSolver() = default;

std::string HypreKrylovSolver::name() const {
  const std::string method = functionsOf(method_).name;
  switch (preconditioner_) {
    case Preconditioner::BoomerAMG:
      return "BoomerAMG-" + method;
    case Preconditioner::diagonal:
      return "diagonal-" + method;
    case Preconditioner::none:
      break;
  }
  return method;
}

int HypreKrylovSolver::iterate(const SparseSystem& A, std::vector<double>& x, double target,
                               int maxIter, SolverPerformance& performance) {
  if (method_ == Method::PCG && !A.symmetricHint && !warnedSymmetry_) {
    warning(
        fmt::format("{}: the matrix for {} is not symmetric; PCG may fail (use GMRES or BiCGSTAB)",
                    name(), controls().field));
    warnedSymmetry_ = true;
  }
  const KrylovFunctions& f = functionsOf(method_);
  HYPRE_ClearAllErrors();
  handOver(A, performance);
  const HypreMatrix& matrix = *matrix_;
  const HypreVector& b = *rhs_;

  auto start = std::chrono::steady_clock::now();
  HypreVector solution(A.firstRow, x);
  performance.assemblySeconds += secondsSince(start);

  start = std::chrono::steady_clock::now();
  const KrylovHandle krylov(f);
  HYPRE_Solver s = krylov.get();
  f.setTol(s, target);  // relative to ||b||: the same residual as ours
  f.setMaxIter(s, maxIter);
  switch (method_) {
    case Method::PCG:
      HYPRE_PCGSetTwoNorm(s, 1);
      HYPRE_PCGSetRecomputeResidual(s, 1);
      break;
    case Method::GMRES:
      HYPRE_GMRESSetKDim(s, kDim_);
      break;
    case Method::BiCGSTAB:
      break;
  }
  switch (preconditioner_) {
    case Preconditioner::BoomerAMG: {
      const HYPRE_PtrToParSolverFcn setup = amg_->prepare(A.firstRow, A.nRows());
      f.setPrecond(s, BoomerAMG::solveFunction(), setup, amg_->handle());
      break;
    }
    case Preconditioner::diagonal:
      f.setPrecond(s, HYPRE_ParCSRDiagScale, HYPRE_ParCSRDiagScaleSetup, nullptr);
      break;
    case Preconditioner::none:
      break;
  }
  hypreCheck(HYPRE_GetError(), f.name);
  hypreCheck(f.setup(s, matrix.parcsr(), b.par(), solution.par()), "Krylov setup");
  performance.setupSeconds += secondsSince(start);

  start = std::chrono::steady_clock::now();
  const HYPRE_Int ierr = f.solve(s, matrix.parcsr(), b.par(), solution.par());
  if (ierr != 0 && ierr != HYPRE_ERROR_CONV) {  // a breakdown: not fatal, the residual tells
    warning(fmt::format("{}: hypre reported '{}' solving for {}", name(), hypreErrorText(ierr),
                        controls().field));
  }
  HYPRE_ClearAllErrors();
  HYPRE_Int iterations = 0;
  f.iterations(s, &iterations);
  if (amg_) amg_->solved(static_cast<int>(iterations));
  solution.copyTo(x);
  performance.solveSeconds += secondsSince(start);
  return iterations;
}

void HypreKrylovSolver::handOver(const SparseSystem& A, SolverPerformance& performance) {
  if (matrix_) return;
  const auto start = std::chrono::steady_clock::now();
  matrix_ = std::make_unique<HypreMatrix>(A);
  rhs_ = std::make_unique<HypreVector>(A.firstRow, A.rhs);
  performance.assemblySeconds += secondsSince(start);
}

double HypreKrylovSolver::residual(const SparseSystem& A, const std::vector<double>& x, double bNorm,
                                   SolverPerformance& performance) {
  if (!distributedRun()) return ControlledLinearSolver::residual(A, x, bNorm, performance);
  handOver(A, performance);
  return matrix_->residualNorm(*rhs_, A.firstRow, x) / bNorm;  // hypre's product over all ranks
}

void HypreKrylovSolver::release() {
  matrix_.reset();
  rhs_.reset();
}

}  // namespace isph
