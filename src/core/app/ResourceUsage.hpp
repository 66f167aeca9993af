#pragma once
// What the process has used, for the end of a solver's log (the scaling benchmark reads it).

namespace isph {

// The peak resident set size of this process so far [MB] (getrusage's ru_maxrss), 0 if unknown.
double peakResidentMegabytes();

}  // namespace isph
