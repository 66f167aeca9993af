#pragma once
// Gravity from constant/g (OpenFOAM's form: `dimensions [0 1 -2 0 0 0 0]; value (0 -9.81 0);`).
#include <filesystem>

#include "core/Types.hpp"

namespace isph {

Vec3 readGravity(const std::filesystem::path& caseDir);

}  // namespace isph
