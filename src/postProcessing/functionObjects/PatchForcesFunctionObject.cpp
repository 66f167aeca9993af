#include "postProcessing/functionObjects/PatchForcesFunctionObject.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/Log.hpp"
#include "core/ParallelRun.hpp"
#include "postProcessing/forces/SetForces.hpp"

namespace isph {

PatchForcesFunctionObject::PatchForcesFunctionObject(const std::string& name, const Dictionary& dict,
                                                     const Time& time)
    : FunctionObject(name, dict),
      set_{readForceSet(name, dict)},
      file_(time.path() / "postProcessing" / name / time.timeName() / "force.dat"),
      out_(file_, fmt::format("function object '{}'", name)) {
  if (isMasterRank()) dropHalfRows(file_.parent_path().parent_path(), file_.filename().string());
}

void PatchForcesFunctionObject::execute(const Time& time, const SolverState& state) {
  const auto forces = setForces({.cloud = state.cloud,
                                 .sets = set_,
                                 .tau = state.tau,
                                 .kernel = state.kernel,
                                 .neighbours = state.neighbours,
                                 .wallFriction = state.wallFriction,
                                 .owned = state.owned});
  if (!isMasterRank()) return;  // a parallel run's file is rank 0's
  std::string text;
  if (!table_) {
    table_.emplace(set_[0], state.cloud.properties.dimension);
    text = table_->header(forces[0]);
  }
  text += table_->row(time.value(), forces[0]);
  out_.write(text);
}

std::string PatchForcesFunctionObject::describe() const {
  const ForceSet& s = set_[0];
  return fmt::format("{}: patchForces on ({}){}, CofR ({} {} {}), {}, every {} step(s) -> {}", name(),
                     fmt::join(s.patchNames, " "),
                     s.facing ? fmt::format(" facing ({} {} {})", s.facing->x(), s.facing->y(), s.facing->z())
                              : std::string(),
                     s.CofR.x(), s.CofR.y(), s.CofR.z(),
                     s.width ? fmt::format("over a width of {} m (2D)", *s.width) : "per metre of width (2D)",
                     writeInterval(), file_.string());
}

namespace {

const bool registered = FunctionObjectRegistry::add(
    "patchForces", [](const std::string& name, const Dictionary& dict, const Time& time) {
      return std::make_unique<PatchForcesFunctionObject>(name, dict, time);
    });

}  // namespace

}  // namespace isph
