// isphLandslideFoam: incompressible SPH for flow-like landslides (the paper's projection
// method, Eqs. 6-11). Reads the particles of the start time, steps them to endTime and
// writes time directories as system/controlDict says; every time directory is a restart.
// The method is chosen by name, isphSchemes `method` (solvers/ParticleSolver.hpp): the projection
// by default, `method wcsph;` the explicit weakly-compressible baseline.
// The function objects of controlDict's `functions` (e.g. patchForces) run after each step.
// Ctrl-C (SIGINT), SIGTERM or SIGHUP (the terminal closed) writes the time at the end of the step
// and then ends the process by that signal (exit status 130, 143 or 129), so a calling Allrun
// stops as well. With adjustTimeStep no a step above maxCo is a warning and one past Co 1 or a wall
// crossing stops the run (isph/timeStepping/FixedStepCheck.hpp). At start it refuses an endTime not after the
// start time, a writeInterval shorter than the step, particles outside the scene or behind a wall
// and speeds far past free fall (isph/startup/StartupChecks.hpp), and a scene edited since particleMesh made 0/ unless
// -force (isph/startup/SceneUpToDate.hpp).
// Progress (time, percent, wall time, time left) goes to ISPH_PROGRESS_FD when runApplication
// sets it (the terminal while the log goes to log.isphLandslideFoam), never to the log.
// With -parallel it runs on the ranks of mpirun -np N (doc/parallel.md: decomposePar first, or
// it decomposes the start time in memory; writes processor<i>/<time>; reconstructPar after);
// rank 0 writes the log and the function objects' files.
#include <fmt/format.h>

#include <chrono>
#include <ctime>
#include <iostream>
#include <optional>

#include "core/Log.hpp"
#include "core/app/Application.hpp"
#include "core/app/OutOfMemory.hpp"
#include "core/app/ResourceUsage.hpp"
#include "core/dictionary/KeywordRecord.hpp"
#include "core/time/ProgressReporter.hpp"
#include "core/time/StopSignal.hpp"
#include "core/time/Time.hpp"
#include "isph/timeStepping/FixedStepCheck.hpp"
#include "isph/startup/SceneUpToDate.hpp"
#include "isph/startup/StartupChecks.hpp"
#include "isph/solvers/StepWithRetry.hpp"
#include "isph/parallel/OwnedParticles.hpp"
#include "isph/solvers/ParticleSolver.hpp"
#include "linearSolvers/ParallelEnvironment.hpp"
#include "parallel/DecomposedCase.hpp"
#include "parallel/Reduce.hpp"
#include "postProcessing/functionObjects/FunctionObjectList.hpp"

namespace {

const isph::ApplicationSpec spec{
    .name = "isphLandslideFoam",
    .description = "Incompressible SPH (projection method) for flow-like landslides and fluids.",
    .options = {{"force", "", "run although system/particleMeshDict is newer than the particles of 0/"},
                {"listKeywords", "", "print every entry it reads from the case's dictionaries (its default, choices or range) and stop"}},
    .arguments = {},
    .parallel = true,
    .recovery = isph::CaseRecovery::allHosts,
};

void run(const isph::ArgList& args) {
  const bool parallel = args.found("parallel");
  if (!parallel && isph::nRanks() > 1) {
    isph::fatalError(fmt::format("started on {} MPI ranks without -parallel: run mpirun -np {} {} -parallel (or "
                                 "runParallel), or without mpirun for a serial run",
                                 isph::nRanks(), isph::nRanks(), spec.name));
  }
  const bool listKeywords = args.found("listKeywords");  // the keyword reference (doc/keywords.md)
  if (listKeywords) isph::enableKeywordRecord();
  isph::checkSceneUpToDate(args.casePath(), args.found("force"));  // an edited scene needs particleMesh again
  isph::Time time(args.casePath(), parallel ? isph::processorName(isph::thisRank()) : std::string());
  isph::stopSignal::install();
  isph::checkEndTime(time);
  isph::FunctionObjectList functions(time);  // first: a typo in controlDict stops the run at once
  std::optional<isph::Building> building(std::in_place, fmt::format("the solver from time {}", time.timeName()));
  const std::unique_ptr<isph::ParticleSolver> solverPtr = isph::ParticleSolver::New(time, parallel);
  isph::ParticleSolver& solver = *solverPtr;
  building.reset();
  isph::checkWriteInterval(time, time.settings().adjustTimeStep ? solver.nextDeltaT(time).value()
                                                                : time.settings().deltaT);
  if (time.settings().writeFormat == isph::WriteFormat::ascii && time.settings().writePrecision < 17) {
    isph::info("    restarts from the times written here are not exact: writeFormat ascii with writePrecision {} "
               "(binary, or 17 digits, read back exactly)",
               time.settings().writePrecision);
  }

  if (listKeywords) {
    std::cout << isph::keywordReference();
    return;
  }
  isph::info("\nStarting time loop\n");
  isph::ProgressReporter progress(spec.name, time.value());
  isph::FixedStepCheck fixedStep(time);  // adjustTimeStep no: above maxCo a warning, past Co 1 the stop
  std::string lastWritten = time.timeName();
  const auto loopStart = std::chrono::steady_clock::now();
  const std::clock_t loopCpuStart = std::clock();
  isph::PhaseTimer& timer = solver.timer();  // the loop's own phases beside the step's
  while (time.run()) {
    {
      auto t = timer.scope("time step choice");
      const isph::TimeStepLimits limits = solver.nextDeltaT(time);
      if (time.settings().adjustTimeStep) time.adjustDeltaT(limits.value());
      ++time;
      building.emplace(fmt::format("the time step to {} ({} particles)", time.timeName(), solver.particles().size()));
      isph::info("Time = {}  deltaT = {:.4g} ({})", time.timeName(), time.deltaT(),
                 time.settings().adjustTimeStep ? limits.limiting() : "fixed");
    }
    const isph::StepReport report = isph::stepWithRetry(time, solver);  // one retry at half the step
    {
      auto t = timer.scope("log");
      for (const auto& perf : report.viscous) isph::logSolverPerformance(perf);
      if (!report.ppe.field.empty()) isph::logSolverPerformance(report.ppe);  // none with method wcsph
      isph::info("    Co = {:.3g}  maxU = {:.4g} m/s  free surface {}  max shift {:.3g} dx  collisions {}  wall safeguard {}  "
                 "wall crossings {}{}",
                 report.courant, report.maxSpeed, report.freeSurface, report.maxShift, report.collisions,
                 report.wallSafeguard, report.wallCrossings,
                 report.densityVariation >= 0 ? fmt::format("  max density variation {:.3g}%", 100 * report.densityVariation)
                                              : std::string());
    }
    fixedStep.check(time, report, lastWritten, progress);
    if (time.writeTime()) {
      solver.write(time);
      lastWritten = time.timeName();
      isph::info("    wrote time {}", time.timeName());
    }
    // The state as written now: the deviatoric stress after the step, the neighbours found
    // afresh over the moved particles (as sampleForces does on the written time).
    // (Only when one is due: the stress is a second strain-rate pass, not to be paid every step.)
    // (A material that slides on the walls exchanges no τ with them: its wall force is pressure
    // plus friction, PatchForces.hpp, and τ is not computed for it.)
    if (functions.anyDue(time)) {
      auto t = timer.scope("function objects");
      const auto* friction = solver.wallFriction();
      const std::vector<char> owned = parallel ? isph::ownedMask(solver.particles()) : std::vector<char>();
      functions.execute(time, {.cloud = solver.particles().cloud, .tau = friction ? nullptr : solver.deviatoricStress(),
                               .kernel = &solver.kernel(), .neighbours = nullptr, .wallFriction = friction,
                               .gravity = &solver.gravity(), .owned = parallel ? &owned : nullptr});
    }
    auto t = timer.scope("log");
    isph::info("{}\n", time.executionTimeLine());
    progress.update(time.value(), time.settings().endTime);
  }
  progress.finish(time.value(), time.settings().endTime);
  {
    auto t = timer.scope("function objects");
    functions.end(time);  // what is written from a whole history (patchForces: the filtered trace)
  }
  isph::info("Wall crossings in the run: {}", solver.wallCrossings());
  if (const std::string above = fixedStep.summary(); !above.empty()) isph::info("{}", above);
  isph::info("{}", solver.safeguardSummary());
  isph::info("Mean neighbours per material particle (last step): {:.1f}", isph::meanNeighbours(solver.particles()));
  if (solver.distributed()) isph::info("{}", solver.distributed()->balanceSummary());
  if (const std::string amg = solver.preconditionerSummary(); !amg.empty()) isph::info("{}", amg);
  isph::info("Peak memory (resident): {:.1f} MB", isph::peakResidentMegabytes());
  // (ExecutionTime is CPU time, as in OpenFOAM: the sum over threads; benchmarks want the wall.)
  const double loopSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - loopStart).count();
  isph::info("Time loop: wall {:.3f} s, CPU {:.3f} s", loopSeconds,
             static_cast<double>(std::clock() - loopCpuStart) / CLOCKS_PER_SEC);
  isph::info("Time spent per phase:\n{}", timer.table(loopSeconds));
  if (isph::stopSignal::caught())
    isph::info("\nStopped by a signal at time {} (written and complete): continue from it with startFrom latestTime;",
               time.timeName());
}

}  // namespace

int main(int argc, char* argv[]) {
  int status = 0;
  {
    isph::ParallelEnvironment parallel(argc, argv);
    status = isph::runApplication(spec, argc, argv, run);
  }
  // Stopped by Ctrl-C or SIGTERM: the last time is written; end by that signal (status 130 or
  // 143), so that an Allrun running this solver stops instead of post-processing a run that
  // did not reach endTime.
  if (status == 0) isph::stopSignal::exitIfCaught();
  return status;
}
