#pragma once
// The frame of every application's main: parse the arguments, print the banner, run the
// body, turn a FatalError into a clear message and a non-zero exit, end the log with "End".
//
//   int main(int argc, char* argv[]) {
//     return isph::runApplication(spec, argc, argv, [](const isph::ArgList& args) { ... });
//   }
#include <functional>

#include "core/app/ArgList.hpp"

namespace isph {

int runApplication(const ApplicationSpec& spec, int argc, const char* const* argv,
                   const std::function<void(const ArgList&)>& body);

}  // namespace isph
