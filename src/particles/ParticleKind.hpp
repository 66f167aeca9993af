#pragma once
// What a particle represents. Stored in the `kind` label field.
#include <string_view>

#include "core/Types.hpp"

namespace isph {

enum class ParticleKind : label {
  material = 0,  // soil or fluid: moves, carries stress
  wall = 1,      // one layer on a solid surface: carries the outward normal and its patch
  dummy = 2,     // layers behind the wall that fill the kernel support
};

constexpr std::string_view kindName(ParticleKind k) {
  switch (k) {
    case ParticleKind::material: return "material";
    case ParticleKind::wall: return "wall";
    case ParticleKind::dummy: return "dummy";
  }
  return "unknown";
}

}  // namespace isph
