#pragma once
// The project's etc/ folder, where #includeEtc looks ($ISPH_ETC, else the source tree's etc/).
#include <filesystem>

namespace isph {

std::filesystem::path etcDirectory();

}  // namespace isph
