// Google Benchmark: assembly (hypre IJ) + BoomerAMG setup + PCG solve of the SPH-like 21-point
// lattice Laplacian (LatticePoisson.hpp) from a zero initial guess, as one PPE step costs.
// Counters, in microseconds per unknown: us/unk (wall clock of all of solve()), cpu_us/unk
// (its CPU time, hypre being single-threaded), and wall-clock assembly, setup, solve.
//   benchLinearSolvers                                      # 2.5k (smoke), 20k, 80k, 320k
//   benchLinearSolvers --benchmark_filter=unknowns:2500/   # the smoke size (ctest)
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <string>

#include "LatticePoisson.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "linearSolvers/LinearSolver.hpp"
#include "linearSolvers/ParallelEnvironment.hpp"

namespace {

using namespace isph;

// Solves A from a zero initial guess once per benchmark iteration with PCG + BoomerAMG and
// reports per-unknown costs: total (wall clock of solve(), including our CSR checks and
// residuals), and hypre's IJ assembly, Krylov+AMG setup and solve separately.
void timeSolves(benchmark::State& state, int unknowns, int toleranceExponent, int reuseSetup) {
  const int n = static_cast<int>(std::lround(std::sqrt(static_cast<double>(unknowns))));
  const SparseSystem A = test::latticePoisson(n, test::Stencil::Sph21);
  const std::string text = "p { solver PCG; preconditioner BoomerAMG; tolerance 1e-" +
                           std::to_string(toleranceExponent) + "; reuseSetup " +
                           std::to_string(reuseSetup) + "; }";
  const auto solver = makeLinearSolver(Dictionary::parse(text, "benchmark").subDict("p"), "p");

  SolverPerformance sum;
  double totalSeconds = 0.0;
  double cpuSeconds = 0.0;
  std::vector<double> x;
  for (auto _ : state) {
    x.assign(A.rhs.size(), 0.0);
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpuStart = std::clock();
    const SolverPerformance perf = solver->solve(A, x);
    cpuSeconds += static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    totalSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!perf.converged) state.SkipWithError(("not converged: " + perf.str()).c_str());
    sum.iterations += perf.iterations;
    sum.assemblySeconds += perf.assemblySeconds;
    sum.setupSeconds += perf.setupSeconds;
    sum.solveSeconds += perf.solveSeconds;
    benchmark::DoNotOptimize(x.data());
  }
  const double solves = static_cast<double>(state.iterations());
  const double perUnknown = 1e6 / (solves * A.nRows());
  state.counters["unknowns"] = A.nRows();
  state.counters["iters"] = sum.iterations / solves;
  state.counters["us/unk"] = totalSeconds * perUnknown;
  state.counters["cpu_us/unk"] = cpuSeconds * perUnknown;  // robust to a busy machine
  state.counters["assembly"] = sum.assemblySeconds * perUnknown;
  state.counters["setup"] = sum.setupSeconds * perUnknown;
  state.counters["solve"] = sum.solveSeconds * perUnknown;
}

// Args: unknowns, -log10(tolerance); the AMG hierarchy is rebuilt for every solve.
void pcgBoomerAMG(benchmark::State& state) {
  timeSolves(state, static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 1);
}
BENCHMARK(pcgBoomerAMG)
    ->ArgNames({"unknowns", "tolExp"})
    ->Args({2500, 8})
    ->Args({20000, 8})
    ->Args({80000, 8})
    ->Args({320000, 8})
    ->Args({20000, 6})
    ->Args({80000, 6})
    ->Args({320000, 6})
    ->MinTime(2.0)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// reuseSetup 5 over 10 solves of the same matrix (tolerance 1e-8): two hierarchies built.
void pcgBoomerAMGReuse5(benchmark::State& state) {
  timeSolves(state, static_cast<int>(state.range(0)), 8, 5);
}
BENCHMARK(pcgBoomerAMGReuse5)
    ->ArgNames({"unknowns"})
    ->Arg(2500)
    ->Arg(320000)
    ->Iterations(10)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  const isph::ParallelEnvironment parallel(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const std::size_t ran = benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return ran > 0 ? 0 : 1;  // a filter that matches nothing fails the smoke test
}
