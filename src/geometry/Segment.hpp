#pragma once
// Elementary operations on the straight segment a-b of a 2D chain.
#include <vector>

#include "geometry/Vec2.hpp"

namespace isph {

// Parameter t in [0, 1] of the point a + t (b - a) closest to p.
double closestParameter(const Vec2& a, const Vec2& b, const Vec2& p);

// Squared distance from p to the segment a-b.
double distanceSquared(const Vec2& a, const Vec2& b, const Vec2& p);

// Whether segments a-b and c-d share a point (crossing, touching or overlapping).
bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d);

// Appends to `t` the parameters t > 0 at which the ray o + t d crosses the closed chain
// `points` (the last point joins the first). Edges parallel to the ray are skipped.
void rayCrossings(const std::vector<Vec2>& points, const Vec2& o, const Vec2& d,
                  std::vector<double>& t);

}  // namespace isph
