#pragma once
// The particles of 0/ are those of the scene in system/particleMeshDict: an edit of the scene
// (a wall friction angle, a barrier moved) takes effect only through particleMesh, and the
// solver would otherwise run the old scene without a word. Refused when particleMeshDict is
// newer than every file of 0/ by more than `copySlack` (cp -r of a case writes the two in
// either order, within moments); -force runs all the same.
#include <filesystem>

namespace isph {

constexpr double copySlackSeconds = 10;

// FatalError naming both files unless `force` (then a warning), when the case has both.
void checkSceneUpToDate(const std::filesystem::path& caseDir, bool force);

}  // namespace isph
