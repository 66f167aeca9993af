#pragma once
// The settings of system/isphSchemes that exclude each other: a FatalIOError at the line of
// the entry that would be ignored, saying what it needs (listed in IsphSchemes.hpp).
#include "core/dictionary/Dictionary.hpp"
#include "isph/IsphSchemes.hpp"

namespace isph {

// Those that exclude each other whatever the scene, in `dict` as `schemes` was read from it
// (IsphSchemes::read; none with method wcsph, which reads none of the projection's entries).
void checkSchemeConflicts(const Dictionary& dict, const IsphSchemes& schemes);
// Those that depend on the scene's materials: `incrementalActs`, the incremental projection
// acts in this scene (incrementalPressure all, or granular with a granular material).
void checkSchemesForScene(const IsphSchemes& schemes, bool incrementalActs);

}  // namespace isph
