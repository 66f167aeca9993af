#include "postProcessing/functionObjects/FunctionObjectList.hpp"

#include <fmt/format.h>

#include "core/Log.hpp"

namespace isph {

FunctionObjectList::FunctionObjectList(const Time& time)
    : FunctionObjectList(time.controlDict().subDictOrEmpty("functions"), time) {}

FunctionObjectList::FunctionObjectList(const Dictionary& functions, const Time& time) {
  for (const auto& e : functions.entries()) {
    if (!e.isDict()) {
      fatalIOError(e.location(), fmt::format("entry '{}' of functions: expected a dictionary such as\n    {} {{ "
                                             "type patchForces; patches (barrier); }}",
                                             e.key(), e.key()));
    }
    const Dictionary& dict = e.dict();
    const std::string type = dict.get<std::string>("type");
    objects_.push_back(FunctionObjectRegistry::create(type, fmt::format("function object type (in '{}')", e.key()),
                                                      dict.entry("type").location(), e.key(), dict, time));
  }
  info("\nFunction objects{}", objects_.empty() ? ": none" : "");
  for (const auto& f : objects_) info("    {}", f->describe());
}

bool FunctionObjectList::anyDue(const Time& time) const {
  for (const auto& f : objects_) {
    if (f->due(time)) return true;
  }
  return false;
}

void FunctionObjectList::execute(const Time& time, const SolverState& state) {
  for (auto& f : objects_) {
    if (f->due(time)) f->execute(time, state);
  }
}

void FunctionObjectList::end(const Time& time) {
  for (auto& f : objects_) f->end(time);
}

}  // namespace isph
