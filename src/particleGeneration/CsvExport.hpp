#pragma once
// A plain CSV of a cloud for a first look before toVTK (`particleMesh -csv`): one particle a
// line, columns x,y,z,kind,material,patch,nx,ny,mass,p. Written atomically.
#include <filesystem>

#include "particles/ParticleCloud.hpp"

namespace isph {

void writeCloudCsv(const std::filesystem::path& file, const ParticleCloud& cloud);

}  // namespace isph
