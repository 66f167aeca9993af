#pragma once
// The times a post-processing utility works on, from -time RANGES, -latestTime and -noZero
// (OpenFOAM's timeSelector), of the case or, with -parallel, of its processor0 directory.
// Warns when the selection is empty.
#include <vector>

#include "core/app/ArgList.hpp"
#include "core/time/TimeName.hpp"
#include "core/time/TimeSelector.hpp"

namespace isph {

TimeSelection timeSelection(const ArgList& args);
std::vector<Instant> selectedTimes(const ArgList& args);

}  // namespace isph
