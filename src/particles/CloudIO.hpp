#pragma once
// Reading and writing a whole cloud in a time directory: <time>/lagrangian/<cloud>/<field>
// for every field, plus cloudProperties (materials, patches, dimension, spacing).
#include <filesystem>

#include "core/fields/FieldIO.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

// Writes the cloud's fields into `timeDir` (normally the staging path of a
// StagedDirectory, so the time directory appears complete or not at all).
// `timeName` is used for the headers' location entries.
void writeCloud(const std::filesystem::path& timeDir, const std::string& timeName, const ParticleCloud& cloud,
                const FieldWriteOptions& options);

// Reads cloud `name` from `timeDir`; every field must be present and of equal length.
ParticleCloud readCloud(const std::filesystem::path& timeDir, const std::string& name);

// The cloud's cloudProperties alone (materials, patches, dimension, spacing, lattice).
CloudProperties readCloudProperties(const std::filesystem::path& timeDir, const std::string& name);

}  // namespace isph
