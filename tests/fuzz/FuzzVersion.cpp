// The version the fuzzers' FoamFile headers name (the main build generates it from git).
#include "core/Version.hpp"

namespace isph {
const char* gitVersion() { return "fuzz"; }
}  // namespace isph
