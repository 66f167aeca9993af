#pragma once
// Validity checks of user-given point lists, done before a shape is built. Each returns the
// first problem found, with the index of the point to blame (so that readers can name its
// line in a dictionary or CSV file), or nothing when the points are valid.
#include <optional>
#include <string>
#include <vector>

#include "geometry/Vec2.hpp"

namespace isph {

struct ShapeProblem {
  std::string message;
  int point = -1;  // index of the offending point, -1 if none in particular
};

// An open chain: at least 2 points, no zero-length segment, no segment crossing or folding
// back onto another.
std::optional<ShapeProblem> polylineProblem(const std::vector<Vec2>& points);

// A polygon (closed implicitly; a repeated first point at the end is allowed): at least 3
// distinct points, no zero-length edge, non-zero area, no crossing edges.
std::optional<ShapeProblem> polygonProblem(const std::vector<Vec2>& points);

// A profile curve: at least 2 points with x strictly increasing or strictly decreasing.
std::optional<ShapeProblem> profileCurveProblem(const std::vector<Vec2>& points);

// Two valid profile curves: a non-empty common x range and upper nowhere below lower.
std::optional<ShapeProblem> profileBandProblem(const std::vector<Vec2>& upper,
                                               const std::vector<Vec2>& lower);

}  // namespace isph
