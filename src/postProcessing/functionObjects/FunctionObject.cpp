#include "postProcessing/functionObjects/FunctionObject.hpp"

#include <fmt/format.h>

namespace isph {

FunctionObject::FunctionObject(std::string name, const Dictionary& dict)
    : name_(std::move(name)), writeInterval_(dict.getOrDefault<label>("writeInterval", 1)) {
  if (writeInterval_ < 1) {
    fatalIOError(dict.entry("writeInterval").location(),
                 fmt::format("keyword 'writeInterval' of function object '{}' is {}; expected a whole number of "
                             "time steps >= 1",
                             name_, writeInterval_));
  }
}

}  // namespace isph
