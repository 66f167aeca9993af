#include "isph/stages/Projection.hpp"

namespace isph {

std::unique_ptr<Projection> Projection::New(const StageSetup& setup) {
  return ProjectionRegistry::create("plain", "projection", setup.schemes.location(), setup);
}

}  // namespace isph
