#pragma once
// The run-out of a flow: how far its front has travelled along a direction. The front is the
// farthest material particle, measured from `origin` along `direction`, among those within
// `maxHeight` of the origin across the direction in the x-y plane (so that spray above the
// flow, or a splash up a wall, does not count; in 3D the height is along heightAxis, not the
// distance from the line: a front across a flume's width counts at every z), plus half a
// spacing: a particle stands for the cell around it.
// A particle counts only if it has at least `minNeighbours` material particles within 1.5
// spacings, so that a lone particle ahead of the front is not taken for it (0 to count all).
#include <optional>

#include "core/Types.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

struct RunOutSpec {
  Vec3 origin = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();  // normalised by runOut
  double maxHeight = 1e300;        // across the direction, from the origin
  int minNeighbours = 0;
};

// The axis the height is measured along: z × direction (the direction turned by 90° in the
// x-y plane: the bed's normal for a direction along the bed), y for a direction along z.
Vec3 heightAxis(const Vec3& direction);

// The front position along the direction; nothing when no material particle qualifies.
std::optional<double> runOut(const ParticleCloud& cloud, const RunOutSpec& spec);

}  // namespace isph
