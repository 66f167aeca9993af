#include "geometry/ShapeChecks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geometry/Polygon.hpp"
#include "geometry/Profile.hpp"
#include "geometry/Segment.hpp"

namespace isph {

namespace {

std::string str(const Vec2& p) { return fmt::format("({:.6g} {:.6g})", p.x(), p.y()); }

double extent(const std::vector<Vec2>& points) {
  Vec2 lo = points.front(), hi = points.front();
  for (const Vec2& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

// Segments s = (p[s], p[s+1 mod n]); adjacent ones share a point, which is not a crossing
// unless one folds back onto the other.
std::optional<ShapeProblem> chainProblem(const std::vector<Vec2>& p, bool closed) {
  const std::size_t n = p.size();
  const std::size_t nSeg = closed ? n : n - 1;
  const double tiny = 1e-12 * extent(p);
  for (std::size_t s = 0; s < nSeg; ++s) {
    if ((p[(s + 1) % n] - p[s]).norm() <= tiny) {
      return ShapeProblem{
          fmt::format("points {} and {} coincide at {}", s + 1, (s + 1) % n + 1, str(p[s])),
          static_cast<int>((s + 1) % n)};
    }
  }
  auto adjacent = [&](std::size_t a, std::size_t b) {
    return b == a + 1 || (closed && a == 0 && b == nSeg - 1);
  };
  for (std::size_t a = 0; a < nSeg; ++a) {
    const Vec2 &a0 = p[a], &a1 = p[(a + 1) % n];
    const Vec2 aLo = a0.cwiseMin(a1), aHi = a0.cwiseMax(a1);
    for (std::size_t b = a + 1; b < nSeg; ++b) {
      const Vec2 &b0 = p[b], &b1 = p[(b + 1) % n];
      if (adjacent(a, b)) {
        // Folding back: the two segments are collinear and point in opposite directions.
        const bool wrap = closed && a == 0 && b == nSeg - 1;
        const Vec2 u = (a1 - a0).normalized(), v = (b1 - b0).normalized();
        if (std::abs(cross(u, v)) < 1e-9 && u.dot(v) < 0) {
          const std::size_t corner = wrap ? 0 : b;
          return ShapeProblem{fmt::format("the line folds back onto itself at point {} {}",
                                          corner + 1, str(p[corner])),
                              static_cast<int>(corner)};
        }
        continue;
      }
      if ((b0.cwiseMin(b1).array() > aHi.array()).any() ||
          (b0.cwiseMax(b1).array() < aLo.array()).any())
        continue;
      if (segmentsIntersect(a0, a1, b0, b1)) {
        return ShapeProblem{fmt::format("it crosses itself: segment {}-{} meets segment {}-{}",
                                        a + 1, (a + 1) % n + 1, b + 1, (b + 1) % n + 1),
                            static_cast<int>(b)};
      }
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<ShapeProblem> polylineProblem(const std::vector<Vec2>& points) {
  if (points.size() < 2)
    return ShapeProblem{fmt::format("a polyline needs at least 2 points, found {}", points.size())};
  return chainProblem(points, false);
}

std::optional<ShapeProblem> polygonProblem(const std::vector<Vec2>& input) {
  std::vector<Vec2> points = input;
  if (points.size() > 1 && points.front() == points.back()) points.pop_back();
  if (points.size() < 3) {
    return ShapeProblem{
        fmt::format("a polygon needs at least 3 distinct points, found {}", points.size())};
  }
  if (auto problem = chainProblem(points, true)) return problem;
  const double area = 0.5 * std::abs(signedDoubleArea(points));
  const double scale = extent(points);
  if (area <= 1e-9 * scale * scale)
    return ShapeProblem{"the polygon has zero area (its points lie on one line)"};
  return std::nullopt;
}

std::optional<ShapeProblem> profileCurveProblem(const std::vector<Vec2>& points) {
  if (points.size() < 2)
    return ShapeProblem{fmt::format("a profile needs at least 2 points, found {}", points.size())};
  const double direction = points.back().x() - points.front().x();
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const double dx = points[k + 1].x() - points[k].x();
    if (dx == 0 || (dx > 0) != (direction > 0)) {
      return ShapeProblem{
          fmt::format(
              "x must increase (or decrease) strictly along a profile; points {} {} and {} {} "
              "break that",
              k + 1, str(points[k]), k + 2, str(points[k + 1])),
          static_cast<int>(k + 1)};
    }
  }
  return std::nullopt;
}

std::optional<ShapeProblem> profileBandProblem(const std::vector<Vec2>& upper,
                                               const std::vector<Vec2>& lower) {
  auto range = [](const std::vector<Vec2>& c) {
    return std::pair{std::min(c.front().x(), c.back().x()), std::max(c.front().x(), c.back().x())};
  };
  const auto [u0, u1] = range(upper);
  const auto [l0, l1] = range(lower);
  const double x0 = std::max(u0, l0), x1 = std::min(u1, l1);
  if (!(x1 > x0)) {
    return ShapeProblem{fmt::format(
        "the upper profile (x from {:.6g} to {:.6g}) and the lower one (x from {:.6g} to "
        "{:.6g}) share no x range",
        u0, u1, l0, l1)};
  }
  const Profile band(upper, lower);
  std::vector<Vec2> all = upper;
  all.insert(all.end(), lower.begin(), lower.end());
  const double tolerance = 1e-6 * extent(all);  // rounding of the given coordinates
  for (double x : band.breakpoints()) {
    const double gap = band.top(x) - band.bottom(x);
    if (gap < -tolerance) {
      return ShapeProblem{
          fmt::format("the profiles cross: at x = {:.9g} the upper one (y = {:.9g}) lies below the "
                      "lower one (y = {:.9g})",
                      x, band.top(x), band.bottom(x))};
    }
  }
  return std::nullopt;
}

}  // namespace isph
