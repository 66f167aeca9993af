#include "core/EtcFiles.hpp"

#include <cstdlib>

#ifndef ISPH_ETC_DIR
#error "ISPH_ETC_DIR must be defined by the build"
#endif

namespace isph {

std::filesystem::path etcDirectory() {
  if (const char* env = std::getenv("ISPH_ETC"); env && *env) return env;
  return ISPH_ETC_DIR;
}

}  // namespace isph
