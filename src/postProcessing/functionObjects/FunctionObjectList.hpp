#pragma once
// The function objects of system/controlDict's `functions` dictionary (FunctionObject.hpp),
// created by `type` at the start of the run; execute() runs those due at the end of a step.
// No `functions` entry: an empty list. An unknown type is a FatalError at its entry that lists
// the available types.
#include <memory>
#include <vector>

#include "core/time/Time.hpp"
#include "postProcessing/functionObjects/FunctionObject.hpp"

namespace isph {

class FunctionObjectList {
 public:
  // Reads time.controlDict()'s `functions` and logs the active function objects.
  explicit FunctionObjectList(const Time& time);
  FunctionObjectList(const Dictionary& functions, const Time& time);

  std::size_t size() const { return objects_.size(); }
  const FunctionObject& operator[](std::size_t i) const { return *objects_[i]; }

  // Whether some function object is due at this step (the solver then computes what they read).
  bool anyDue(const Time& time) const;
  void execute(const Time& time, const SolverState& state);
  // Every function object's end(), once after the time loop.
  void end(const Time& time);

 private:
  std::vector<std::unique_ptr<FunctionObject>> objects_;
};

}  // namespace isph
