#pragma once
// The deviatoric (plastic or viscous) term of the predictor, Eq. 6: u* = uⁿ + dt (∇·τ/ρ + g)
// (+ the pressure force the projection lags, + the Coulomb wall friction), a stage of the
// projection step chosen by name with isphSchemes `viscousTerm`:
//   implicit  SemiImplicitDeviatoricTerm: the term solved semi-implicitly (no viscous
//             time-step limit), the bed friction settled in the same solve (the default)
//   explicit  ExplicitDeviatoricTerm: the explicit sum of Eq. 6 as the paper writes it,
//             with the viscous time-step limit (also a scene with no deviatoric stress:
//             gravity alone)
#include <memory>
#include <string>
#include <vector>

#include "core/Registry.hpp"
#include "isph/timeStepping/StepReport.hpp"
#include "isph/timeStepping/StepState.hpp"
#include "isph/stages/StepContext.hpp"

namespace isph {

class DeviatoricTerm {
 public:
  // The term that `viscousTerm` names (implicit by default); the explicit one (gravity alone)
  // where no material has a deviatoric stress.
  static std::unique_ptr<DeviatoricTerm> New(const StageSetup& setup);
  virtual ~DeviatoricTerm() = default;

  // Whether the term is solved implicitly (else its viscous time-step limit applies).
  virtual bool isImplicit() const = 0;
  // One line for the log's list of schemes.
  virtual std::string describe() const = 0;
  // u* of the material (Eq. 6) with the viscosities of c.viscousStress, gravity and the wall
  // friction (c.wallFriction receives the walls' share); the deviatoric stress that acted is
  // kept in c.viscousStress. A failed linear solve is in report.viscous. Returns the largest
  // acceleration of an explicit deviatoric term (0 when implicit).
  virtual double predict(StepContext& c, double dt, long stepsTaken, std::vector<Vec3>& ustar,
                         StepReport& report) = 0;
  // The material particles were renumbered (reordering, a write, a failed solve).
  virtual void renumbered() {}
  // What the term carries to the next step, into and out of a restart's StepState.
  virtual void saveState(StepState&) const {}
  virtual void restoreState(const StepState&) {}
  // Its linear solvers' work for the end of the log (empty: none).
  virtual std::string summary() const { return {}; }
};

using DeviatoricTermRegistry = Registry<DeviatoricTerm, const StageSetup&>;

}  // namespace isph
