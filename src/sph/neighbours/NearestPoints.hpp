#pragma once
// For each query point the nearest of a set of target points within a radius, through a
// CellGrid (no O(N²) search); equally near targets are told apart by their ids, the smaller
// wins, so the answer depends only on the points, not on their order or on which subset of
// the targets a rank holds. Used for each dummy particle's wall particle.
#include <vector>

#include "core/Types.hpp"

namespace isph {

// The index into `targets` of the target nearest to each query point (closer than `radius`),
// or -1 where none is.
std::vector<int> nearestPoints(const std::vector<Vec3>& targets, const std::vector<label>& targetIds,
                               const std::vector<Vec3>& queries, double radius, int dimension);

}  // namespace isph
