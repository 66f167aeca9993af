#pragma once

namespace isph {
// `git describe --tags --always --dirty` of the source tree at build time.
const char* gitVersion();
}  // namespace isph
