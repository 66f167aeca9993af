#pragma once
// One time step with one retry (issue 4): when the pressure Poisson equation or the implicit
// viscous step does not converge within maxIter (StepReport::failedSolve), the step is taken
// back (the solver leaves the particles as at the step start), redone from the same start with
// half the step, and a warning says so. A smaller step also helps the viscous system: its
// mass term m/dt grows against the viscous one. If the
// retry does not converge either, the run stops with a FatalError that says which solve
// failed, when (the time of each attempt, its deltaT, residual and iterations) and where to
// act (system/isphSolution, controlDict); the last written time directory is untouched.
//
// After a successful retry an adjustTimeStep run sizes its next step as usual (growth from
// the halved one limited by maxGrowth); a fixed-step run goes back to its deltaT.
#include <functional>

#include "core/time/Time.hpp"
#include "isph/solvers/ParticleSolver.hpp"

namespace isph {

// `step` advances the particles by time.deltaT() and, when one of its solves fails, leaves them
// as at the step start (ParticleSolver::step does). Call after ++time.
StepReport stepWithRetry(Time& time, const std::function<StepReport(const Time&)>& step);

inline StepReport stepWithRetry(Time& time, ParticleSolver& solver) {
  return stepWithRetry(time, [&solver](const Time& t) { return solver.step(t); });
}

}  // namespace isph
