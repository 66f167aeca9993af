#pragma once
// The header every log starts with, in OpenFOAM's shape: application, version, case,
// date, host and how many processes and threads run.
#include <string>

#include "core/app/ArgList.hpp"

namespace isph {

std::string banner(const ArgList& args);

// Threads the run uses (OpenMP's maximum; 1 without OpenMP).
int threadCount();

}  // namespace isph
