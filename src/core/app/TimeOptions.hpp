#pragma once
// The times a post-processing utility works on, from -time RANGES, -latestTime and -noZero
// (OpenFOAM's timeSelector), of the case or, with -parallel, of its processor0 directory.
// An empty selection is nothing to do: a FatalError (a non-zero exit, as OpenFOAM's), or, for a
// tool that only lists (isphListTimes, `EmptySelection::warn`), a warning.
#include <vector>

#include "core/app/ArgList.hpp"
#include "core/time/TimeName.hpp"
#include "core/time/TimeSelector.hpp"

namespace isph {

TimeSelection timeSelection(const ArgList& args);
enum class EmptySelection { error, warn };
std::vector<Instant> selectedTimes(const ArgList& args, EmptySelection empty = EmptySelection::error);

}  // namespace isph
