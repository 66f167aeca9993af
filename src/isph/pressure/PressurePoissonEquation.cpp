#include "isph/pressure/PressurePoissonEquation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "core/Log.hpp"
#include "core/ResizeForOverwrite.hpp"
#include "isph/pressure/PpeDirichletParticles.hpp"
#include "isph/walls/WallBoundaryPressure.hpp"
#include "isph/parallel/GhostExchange.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

PressurePoissonEquation::PressurePoissonEquation(const PpeSettings& settings, bool tensionCutoff,
                                                 std::unique_ptr<LinearSolver> solver, std::vector<char> keepCompressed)
    : settings_(settings),
      tensionCutoff_(tensionCutoff),
      solver_(std::move(solver)),
      keepCompressed_(std::move(keepCompressed)) {}


void PressurePoissonEquation::assemble(const ParticleSystem& ps, const Kernel& kernel,
                                       const KernelGradientCorrection& L, const std::vector<Vec3>& ustar,
                                       const std::vector<char>& freeSurfaceIn, const Vec3& g, double dt) {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  const std::size_t nMat = ps.nMaterial;
  const std::vector<char> flags = ppeDirichletParticles(ps, kernel, freeSurfaceIn, keepCompressed_);
  const double W0 = kernel.W(0.0);
  const double halfDx = 0.5 * ps.dx;
  const double relaxation = settings_.boundaryRelaxation;

  // One row per material particle, in the particles' order, whether or not it is an unknown:
  // the Dirichlet ones are identity rows with their known value (decoupled: the unknowns next
  // to them take that value to their right-hand side). So the matrix keeps its size and
  // numbering from step to step as the free surface changes, and an AMG hierarchy can be
  // reused (`p { reuseSetup N; }`); until 2026-12-01 the Dirichlet particles were left out,
  // the size changed every step and every solve built its hierarchy afresh.
  dirichlet_.assign(flags.begin(), flags.end());

  // (parallel: the rows of the own material particles, numbered over all ranks: ps.globalRow)
  const long nRows = static_cast<long>(ps.ownMaterial());
  system_.firstRow = ps.firstRow;
  system_.rowStart.assign(static_cast<std::size_t>(nRows) + 1, 0);
  for (long r = 0; r < nRows; ++r) {
    const auto a = static_cast<std::size_t>(r);
    int count = 1;
    if (!flags[a]) {
      for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
        const auto b = static_cast<std::size_t>(nl.index[static_cast<std::size_t>(k)]);
        count += b < nMat && !flags[b];
      }
    }
    system_.rowStart[static_cast<std::size_t>(r) + 1] = system_.rowStart[static_cast<std::size_t>(r)] + count;
  }
  const auto nnz = static_cast<std::size_t>(system_.rowStart.back());
  resizeForOverwrite(system_.columns, nnz);  // every entry is written below
  resizeForOverwrite(system_.values, nnz);
  system_.rhs.resize(static_cast<std::size_t>(nRows));

  const double h = kernel.h();
  const double eta2 = settings_.laplacianEta * settings_.laplacianEta * h * h;
  const double theta0 = ps.latticeSum;
  const PpeSource type = settings_.source;
  const bool consistent = settings_.laplacianCorrection;
  system_.symmetricHint = !consistent;
  // Each source needs only its own sums: θ* (a kernel value per pair) for the density-invariant
  // one, the divergence of u* for the others.
  const bool needThetaStar = type == PpeSource::densityInvariant;
  const bool needDivergence = type != PpeSource::densityInvariant;

  // Each pair's offset and Eq. 10 coefficient are computed once per row, into a buffer per
  // thread, and read by the correction's two passes and the row's own.
#pragma omp parallel
  {
    std::vector<Vec3> pairOffset;
    std::vector<double> pairC0;
#pragma omp for schedule(static)
    for (long r = 0; r < nRows; ++r) {
      const auto a = static_cast<std::size_t>(r);
      if (flags[a]) continue;  // a Dirichlet row: below
      const Vec3& xa = c.positions[a];
      const Vec3 dxa = dt * ustar[a];
      const double ma = ps.rho[a] * ps.volume[a];
      const long k0 = nl.start[a], nk = nl.start[a + 1] - k0;
      pairOffset.resize(static_cast<std::size_t>(nk));
      pairC0.resize(static_cast<std::size_t>(nk));
      auto pos = static_cast<std::size_t>(system_.rowStart[static_cast<std::size_t>(r)]);
      const std::size_t diag = pos++;
      double diagonal = 0, rhsWall = 0;
      double thetaN = ps.volume[a] * W0, thetaStar = thetaN, divergence = 0;
      bool nearBoundary = false;
      double thetaLattice = ps.volume[a] * W0;  // θⁿ with the wall layers moved onto the lattice
      // First-order correction (consistent Laplacian): d_a = Σ_b 2 V_b F_ab r²/(r²+η²) x_ab
      // vanishes in a full support; where the support is cut, the row gains −(m_a/ρ_a) d_a·∇p_a
      // with the renormalised gradient, so a linear pressure field has a zero Laplacian.
      Vec3 Ld = Vec3::Zero();
      Vec3 d = Vec3::Zero();
      for (long j = 0; j < nk; ++j) {
        const auto kk = static_cast<std::size_t>(k0 + j);
        const auto b = static_cast<std::size_t>(nl.index[kk]);
        const Vec3 xab = xa - c.positions[b];
        const double r2 = xab.squaredNorm();
        const double mb = ps.rho[b] * ps.volume[b];
        const double rhoSum = ps.rho[a] + ps.rho[b];
        pairOffset[static_cast<std::size_t>(j)] = xab;
        pairC0[static_cast<std::size_t>(j)] =
            ma * mb * 8.0 / (rhoSum * rhoSum) * nl.F[kk] * r2 / (r2 + eta2);  // ≤ 0, Eq. 10
        if (consistent) d += 2.0 * ps.volume[b] * nl.F[kk] * r2 / (r2 + eta2) * xab;
      }
      if (consistent) {
        Ld = L[a].transpose() * d * (ma / ps.rho[a]);
        // Keep the M-matrix sign pattern: where the correction would turn a coupling positive
        // (a badly cut support: the tip of a front, a splash), the row stays uncorrected.
        for (long j = 0; j < nk; ++j) {
          const auto kk = static_cast<std::size_t>(k0 + j);
          const auto b = static_cast<std::size_t>(nl.index[kk]);
          if (pairC0[static_cast<std::size_t>(j)] +
                  ps.volume[b] * nl.F[kk] * Ld.dot(pairOffset[static_cast<std::size_t>(j)]) >
              0) {
            Ld.setZero();
            break;
          }
        }
      }
      for (long j = 0; j < nk; ++j) {
        const auto kk = static_cast<std::size_t>(k0 + j);
        const auto b = static_cast<std::size_t>(nl.index[kk]);
        const Vec3& xab = pairOffset[static_cast<std::size_t>(j)];
        const double C = pairC0[static_cast<std::size_t>(j)]       // ≤ 0, Eq. 10
                         + ps.volume[b] * nl.F[kk] * Ld.dot(xab);  // correction
        thetaN += ps.volume[b] * nl.W[kk];
        if (ps.isMaterial(b)) thetaLattice += ps.volume[b] * nl.W[kk];
        if (ps.isMaterial(b)) {
          diagonal -= C;
          if (!flags[b]) {
            system_.columns[pos] = ps.globalRow(b);
            system_.values[pos] = C;
            ++pos;
          }
          nearBoundary = nearBoundary || freeSurfaceIn[b];
          if (needThetaStar)
            thetaStar += ps.volume[b] * kernel.W((xab + dxa - dt * ustar[b]).norm());
          if (needDivergence)
            divergence += ps.volume[b] * (ustar[b] - ustar[a]).dot(L[a] * (nl.F[kk] * xab));
        } else {
          // Wall or dummy: p_b = p_a + δ_ab (WallBoundaryPressure); C_ab (p_a − p_b) = −C_ab δ_ab.
          rhsWall += C * wallPressureIncrement(ps, ustar, g, a, b, dt);
          nearBoundary = true;
          thetaLattice += ps.volume[b] * kernel.W((xab + halfDx * wallNormal(ps, b)).norm());
          thetaStar += ps.volume[b] * nl.W[kk];  // the wall moves with a: no relative motion
        }
      }
      system_.columns[diag] = ps.globalRow(a);
      system_.values[diag] = diagonal;
      // The reference of the density-invariant source: the full-lattice sum θ₀ inside. Where
      // the support reaches the free surface or a wall, the present sum θⁿ (a cut support must
      // not be pulled in, and the wall layers sit half a spacing off the lattice), less a tenth
      // per step of any compression beyond the lattice density, measured with the wall layers
      // moved half a spacing back onto the lattice (θ_lattice = θ₀ for material at rest on a
      // flat wall). Without that, compaction next to p = 0 and walls is never undone: a
      // granular deposit lost a third of its volume and clumped.
      const double thetaRef =
          nearBoundary ? thetaN - relaxation * std::max(thetaLattice - 1.01 * theta0, 0.0) : theta0;
      double source = 0;
      switch (type) {
        case PpeSource::densityInvariant:
          source = (thetaRef - thetaStar) / (thetaRef * dt * dt);
          break;
        case PpeSource::divergence:
          source = divergence / dt;
          break;
        case PpeSource::mixed:
          source = divergence / dt + settings_.alpha * (thetaRef - thetaN) / (thetaRef * dt * dt);
          break;
      }
      // A = −(Eq. 10 × m_a): A p = −m_a S_a − Σ_wall C_ab δ_ab
      system_.rhs[static_cast<std::size_t>(r)] = -ma * source - rhsWall;
    }
  }  // omp parallel
  // The Dirichlet rows, scaled like the unknowns' (their mean diagonal) so that neither
  // dominates the residual: s p_a = s p_D.
  double diagonalSum = 0;
  long unknowns = 0;
  for (std::size_t a = 0; a < static_cast<std::size_t>(nRows); ++a) {
    if (flags[a]) continue;
    diagonalSum += system_.values[static_cast<std::size_t>(system_.rowStart[a])];
    ++unknowns;
  }
  diagonalSum = sumOverRanks(diagonalSum), unknowns = sumOverRanks(unknowns);  // parallel: all ranks'
  const double scale = unknowns > 0 && diagonalSum > 0 ? diagonalSum / static_cast<double>(unknowns) : 1.0;
  for (std::size_t a = 0; a < static_cast<std::size_t>(nRows); ++a) {
    if (!flags[a]) continue;
    const auto at = static_cast<std::size_t>(system_.rowStart[a]);
    system_.columns[at] = ps.globalRow(a);
    system_.values[at] = scale;
    system_.rhs[a] = 0.0;
  }
}

SolverPerformance PressurePoissonEquation::solve(ParticleSystem& ps, const Kernel& kernel,
                                                 const KernelGradientCorrection& L, const std::vector<Vec3>& ustar,
                                                 const std::vector<char>& freeSurface, const Vec3& g, double dt) {
  const auto start = std::chrono::steady_clock::now();
  assemble(ps, kernel, L, ustar, freeSurface, g, dt);
  assemblySeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  auto& p = ps.cloud.p;
  const std::size_t nRows = ps.ownMaterial();  // (parallel: the own rows)
  std::vector<double> x(p.begin(), p.begin() + static_cast<long>(nRows));  // warm start
  for (std::size_t a = 0; a < nRows; ++a) {
    if (dirichlet_[a]) x[a] = 0.0;
  }
  SolverPerformance perf = solver_->solve(system_, x);
  for (std::size_t a = 0; a < nRows; ++a) {
    p[a] = dirichlet_[a] ? 0.0 : x[a];
    // Neither soil nor a breaking water front carries tension; SPH suction at a stretching
    // front is also what launches the tensile instability.
    if (tensionCutoff_) p[a] = std::max(p[a], 0.0);
  }
  exchangeGhosts(ps, p);  // parallel: the walls' pressures (WallBoundary::update) read it at ghosts
  return perf;
}

}  // namespace isph
