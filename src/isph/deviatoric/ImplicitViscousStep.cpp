#include "isph/deviatoric/ImplicitViscousStep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/Log.hpp"
#include "core/ResizeForOverwrite.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "isph/timeStepping/StepState.hpp"
#include "isph/walls/WallBoundaryPressure.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

namespace {

// Particle a's velocity from the interleaved unknowns of the coupled system.
Vec3 velocityOf(const std::vector<double>& xv, std::size_t a, int dim) {
  Vec3 u = Vec3::Zero();
  for (int d = 0; d < dim; ++d) u[d] = xv[a * static_cast<std::size_t>(dim) + static_cast<std::size_t>(d)];
  return u;
}

}  // namespace

ImplicitViscousStep::ImplicitViscousStep(const Dictionary& solverDict, int dimension, int frictionPasses)
    : maxFrictionPasses_(frictionPasses) {
  warmFromLastIncrement_ =
      solverDict.getChoiceOrDefault("warmStart", {"predictor", "lastIncrement"}, "predictor") == "lastIncrement";
  info("    velocity solve warm start: {}", warmFromLastIncrement_
                                                  ? "the explicit predictor plus the last step's viscous increment"
                                                  : "the explicit predictor u + dt g");
  static const char* names[] = {"Ux", "Uy", "Uz"};
  for (int d = 0; d < dimension; ++d) solvers_.push_back(makeLinearSolver(solverDict, names[d]));
  coupledSolver_ = makeLinearSolver(solverDict, "U");
}

ImplicitViscousStep::~ImplicitViscousStep() = default;

int ImplicitViscousStep::solvesDone() const {
  int n = coupledSolver_->solvesDone();
  for (const auto& s : solvers_) n += s->solvesDone();
  return n;
}

int ImplicitViscousStep::preconditionersBuilt() const {
  int n = coupledSolver_->preconditionersBuilt();
  for (const auto& s : solvers_) n += s->preconditionersBuilt();
  return n;
}

void ImplicitViscousStep::saveState(StepState& state) const {
  state.frictionStates.clear();
  for (const auto k : activeSet_.keptStates()) state.frictionStates.push_back(static_cast<label>(k));
  state.slipDirections = activeSet_.keptDirections();
  state.viscousIncrements = keptIncrement_;
  state.viscousIncrementDt = keptDt_;
}

void ImplicitViscousStep::restoreState(const StepState& state) {
  std::vector<WallFrictionActiveSet::State> states(state.frictionStates.size());
  for (std::size_t i = 0; i < states.size(); ++i) {
    const label v = state.frictionStates[i];
    if (v < 0 || v > 2) fatalError(fmt::format("uniform/frictionStates: state {} of particle {} is not 0, 1 or 2", v, i));
    states[i] = static_cast<WallFrictionActiveSet::State>(v);
  }
  activeSet_.restoreKept(std::move(states), state.slipDirections);
  keptIncrement_ = state.viscousIncrements;
  keptDt_ = state.viscousIncrementDt;
}

void ImplicitViscousStep::renumbered() {
  for (auto& s : solvers_) s->rebuildPreconditionerForNextSolve();
  coupledSolver_->rebuildPreconditionerForNextSolve();
}

std::vector<SolverPerformance> ImplicitViscousStep::solve(const ParticleSystem& ps, const MaterialTable& materials,
                                                          const std::vector<double>& eta,
                                                          const WallFriction* friction, const Vec3& g, double dt,
                                                          double h, std::vector<Vec3>& ustar) {
  const auto start = std::chrono::steady_clock::now();
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const long nMat = static_cast<long>(ps.ownMaterial());  // (parallel: the own rows, numbered ps.globalRow)
  const double eta2 = 0.01 * h * h;
  const bool drag = friction && friction->active();

  // The pattern: each material particle and its material neighbours.
  system_.firstRow = ps.firstRow;
  system_.symmetricHint = true;
  system_.rowStart.assign(static_cast<std::size_t>(nMat) + 1, 0);
  for (long a = 0; a < nMat; ++a) {
    int count = 1;
    for (long k = nl.start[static_cast<std::size_t>(a)]; k < nl.start[static_cast<std::size_t>(a) + 1]; ++k) {
      count += ps.isMaterial(static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)]));
    }
    system_.rowStart[static_cast<std::size_t>(a) + 1] = system_.rowStart[static_cast<std::size_t>(a)] + count;
  }
  const auto nnz = static_cast<std::size_t>(system_.rowStart.back());
  resizeForOverwrite(system_.columns, nnz);  // every entry is written below
  resizeForOverwrite(system_.values, nnz);
  system_.rhs.resize(static_cast<std::size_t>(nMat));

  const int dim = ps.dimension;
  std::vector<Vec3> rhs(static_cast<std::size_t>(nMat));
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < nMat; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    const double ma = c.mass[a];
    const bool withWalls = materials[static_cast<std::size_t>(c.material[a])].wallContact() == WallContact::noSlip;
    auto pos = static_cast<std::size_t>(system_.rowStart[a]);
    const std::size_t diag = pos++;
    const Vec3& fa = g;
    Vec3 r = ma * (c.U[a] / dt + fa);
    double diagonal = ma / dt;
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto b = static_cast<std::size_t>(nl.index[kk]);
      const bool material = ps.isMaterial(b);
      if (!material && !withWalls) continue;
      const double r2 = (c.positions[a] - c.positions[b]).squaredNorm();
      const double mb = ps.rho[b] * ps.volume[b];
      const double etaB = material ? eta[b] : eta[a];
      const double kappa = -ma * mb * (eta[a] + etaB) / (ps.rho[a] * ps.rho[b]) * nl.F[kk] * r2 / (r2 + eta2);
      diagonal += kappa;
      if (material) {
        system_.columns[pos] = ps.globalRow(b);
        system_.values[pos] = -kappa;
        ++pos;
      } else {
        // The wall as the no-slip term sees it: at rest along the wall, and moving with a in
        // its normal direction and with the gravity increment, both the PPE's to resolve.
        const Vec3& n = wallNormal(ps, b);
        r += kappa * (dt * fa + c.U[a].dot(n) * n);
      }
    }
    system_.columns[diag] = ps.globalRow(a);
    system_.values[diag] = diagonal;
    rhs[a] = r;
  }
  assemblySeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // Coulomb friction on the tangential velocity (numerics.md §3, the wall viscosity of the
  // implicit form), by the active-set iteration of WallFrictionActiveSet: each pass solves
  // with every bed particle's law linearised in its stick/slip state of the last pass (from
  // time n at the first), and the passes stop when no state changes, or at
  // `wallFriction { passes }` of isphSchemes (default 10; 2-4 are typical).
  const std::size_t n = static_cast<std::size_t>(nMat);
  std::vector<SolverPerformance> perf;
  std::vector<double> x(n);
  // Warm start (`U { warmStart }`): the explicit predictor, or that plus the last step's
  // viscous increment (by particle, scaled by dt/dt_last).
  ustar.assign(ps.size(), Vec3::Zero());
  frictionForce_.clear();
  const bool useKept = warmFromLastIncrement_ && keptDt_ > 0;
  for (std::size_t a = 0; a < n; ++a) {
    ustar[a] = c.U[a] + dt * g;
    const auto id = static_cast<std::size_t>(c.origId[a]);
    if (useKept && id < keptIncrement_.size()) ustar[a] += (dt / keptDt_) * keptIncrement_[id];
  }
  if (drag) {
    // The drag acts on the tangential velocity only: it couples the components of a
    // particle, so the components are solved together (one system of dim × N unknowns,
    // interleaved), exactly: an isotropic drag with the normal part moved to the right-hand
    // side would push the material off the wall, or hold it there.
    activeSet_.start(*friction, c.U, c.origId, n);
    lastPasses_ = 0;
    for (int pass = 0; pass < maxFrictionPasses_; ++pass) {
      const auto coupledStart = std::chrono::steady_clock::now();
      assembleCoupled(ps.dimension, rhs);
      assemblySeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - coupledStart).count();
      std::vector<double> xv(n * static_cast<std::size_t>(dim));
      for (std::size_t a = 0; a < n; ++a) {
        for (int d = 0; d < dim; ++d) xv[a * static_cast<std::size_t>(dim) + static_cast<std::size_t>(d)] = ustar[a][d];
      }
      // A later pass changes only the rows of the particles whose state changed: the AMG
      // hierarchy of the first pass still preconditions it (each pass is logged and timed).
      // The passes before the last stop at `relTol` of `U { }`; the last, or a pass after
      // which no state changes, is finished to the tolerance (OpenFOAM's UFinal). The barrier
      // tutorial takes relTol 1e-5 (the others 0): at 3.6 mm a quarter fewer PCG iterations,
      // 551 s against 598 s, every step's states settled (doc/notes/barrier.md). Looser, the
      // inexact passes misclassify: at 10.8 mm 1e-3 left 5 of 2,807 steps unsettled, 1e-2 35
      // of 2,781 (4.23 passes per step against 2.76 at 1e-5; 2026-12-05).
      if (pass > 0) coupledSolver_->keepPreconditionerForNextSolve();
      const bool last = pass + 1 == maxFrictionPasses_;
      perf.push_back(last ? coupledSolver_->solveFinal(coupled_, xv) : coupledSolver_->solve(coupled_, xv));
      ++lastPasses_;
      // The friction force of this solve, in the states it was solved with (before they are
      // classified again): what the walls take (WallFriction::wallTraction).
      frictionForce_.assign(n, Vec3::Zero());
      for (std::size_t a = 0; a < n; ++a) frictionForce_[a] = activeSet_.applied(a, velocityOf(xv, a, dim), dim);
      const bool settled = sumOverRanks(static_cast<long>(activeSet_.update(xv, dim))) == 0;  // parallel: all ranks
      if (settled && !last && coupledSolver_->stopsAtRelTol()) {
        coupledSolver_->keepPreconditionerForNextSolve();  // the same system, to the tolerance
        perf.push_back(coupledSolver_->solveFinal(coupled_, xv));
        for (std::size_t a = 0; a < n; ++a) frictionForce_[a] = activeSet_.applied(a, velocityOf(xv, a, dim), dim);
      }
      for (std::size_t a = 0; a < n; ++a) ustar[a] = velocityOf(xv, a, dim);
      lastSettled_ = settled;
      if (settled) break;
    }
    activeSet_.remember(c.origId);
    keepIncrement(ps, dt, g, ustar);  // (parallel: ustar of the own rows; ghosts follow in ProjectionSolver)
    ++frictionSolves_;
    frictionSettled_ += lastSettled_;
    frictionPassesDone_ += lastPasses_;
    return perf;
  }
  perf.clear();
  for (int d = 0; d < dim; ++d) {
    for (std::size_t a = 0; a < n; ++a) {
      system_.rhs[a] = rhs[a][d];
      x[a] = ustar[a][d];
    }
    perf.push_back(solvers_[static_cast<std::size_t>(d)]->solveFinal(system_, x));
    for (std::size_t a = 0; a < n; ++a) ustar[a][d] = x[a];
  }
  keepIncrement(ps, dt, g, ustar);
  return perf;
}

void ImplicitViscousStep::keepIncrement(const ParticleSystem& ps, double dt, const Vec3& g,
                                        const std::vector<Vec3>& ustar) {
  if (!warmFromLastIncrement_) return;
  const auto& c = ps.cloud;
  std::size_t size = 0;
  for (std::size_t a = 0; a < ps.ownMaterial(); ++a) size = std::max(size, static_cast<std::size_t>(c.origId[a]) + 1);
  keptIncrement_.assign(std::max(size, keptIncrement_.size()), Vec3::Zero());
  for (std::size_t a = 0; a < ps.ownMaterial(); ++a) {
    keptIncrement_[static_cast<std::size_t>(c.origId[a])] = ustar[a] - c.U[a] - dt * g;
  }
  keptDt_ = dt;
}

void ImplicitViscousStep::assembleCoupled(int dim, const std::vector<Vec3>& rhs) {
  const std::size_t n = rhs.size();
  const auto D = static_cast<std::size_t>(dim);
  // Particle a's components are rows D a + d of the block of D × (own rows) (parallel: from
  // D × system_.firstRow, as system_'s columns number the particles over all ranks).
  const long first = system_.firstRow * static_cast<long>(D);
  coupled_.firstRow = first;
  coupled_.symmetricHint = true;
  // Row lengths first (the particle's own block, its material neighbours), then each row
  // filled in place, in parallel.
  coupled_.rowStart.assign(n * D + 1, 0);
  for (std::size_t a = 0; a < n; ++a) {
    const bool onWall = activeSet_.state(a) != WallFrictionActiveSet::State::free;
    const long length = (onWall ? static_cast<long>(D) : 1) + system_.rowStart[a + 1] - system_.rowStart[a] - 1;
    for (std::size_t d = 0; d < D; ++d) coupled_.rowStart[a * D + d + 1] = coupled_.rowStart[a * D + d] + length;
  }
  const auto nnz = static_cast<std::size_t>(coupled_.rowStart.back());
  resizeForOverwrite(coupled_.columns, nnz);  // every entry is written below
  resizeForOverwrite(coupled_.values, nnz);
  coupled_.rhs.resize(n * D);
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < static_cast<long>(n); ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    const auto begin = static_cast<std::size_t>(system_.rowStart[a]);
    const auto end = static_cast<std::size_t>(system_.rowStart[a + 1]);
    const bool onWall = activeSet_.state(a) != WallFrictionActiveSet::State::free;
    const Vec3 f = activeSet_.force(a);
    for (std::size_t d = 0; d < D; ++d) {
      const std::size_t row = a * D + d;
      const int di = static_cast<int>(d);
      auto pos = static_cast<std::size_t>(coupled_.rowStart[row]);
      // The particle's own block: the scalar diagonal plus its friction block.
      coupled_.columns[pos] = first + static_cast<long>(row);
      coupled_.values[pos++] = system_.values[begin] + activeSet_.block(a, di, di);
      if (onWall) {
        for (std::size_t e = 0; e < D; ++e) {
          if (e == d) continue;
          coupled_.columns[pos] = first + static_cast<long>(a * D + e);
          coupled_.values[pos++] = activeSet_.block(a, di, static_cast<int>(e));
        }
      }
      for (std::size_t k = begin + 1; k < end; ++k) {  // the material neighbours, same component
        coupled_.columns[pos] = system_.columns[k] * static_cast<long>(D) + static_cast<long>(d);
        coupled_.values[pos++] = system_.values[k];
      }
      coupled_.rhs[row] = rhs[a][static_cast<long>(d)] + f[static_cast<long>(d)];
    }
  }
}

}  // namespace isph
