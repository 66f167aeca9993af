// The wall types of particleMeshDict, registered by name:
//   polyline { points ((x y 0) ...); }     or pointsFile "constant/bed.csv"; the surface of
//                                          the solid behind it (side: see SceneReader)
//   box      { min (x y 0); max (x y 0); } a solid rectangle
//   polygon  { points ((x y 0) ...); }     a solid polygon (either winding)
#include <fmt/format.h>

#include <algorithm>

#include "core/Registry.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "geometry/Box.hpp"
#include "geometry/Polygon.hpp"
#include "particleGeneration/ShapeInput.hpp"
#include "particleGeneration/WallSurface.hpp"

namespace isph {

namespace {

using WallRegistry = Registry<WallSurface, const Dictionary&, const ShapeContext&>;

// The boundary of a solid walked clockwise: the material (outside) on the left.
std::unique_ptr<WallSurface> solidBoundary(std::vector<Vec2> counterClockwise,
                                           const std::string& type) {
  std::reverse(counterClockwise.begin(), counterClockwise.end());
  return std::make_unique<WallSurface>(Polyline(std::move(counterClockwise), true), type);
}

std::unique_ptr<WallSurface> readPolylineWall(const Dictionary& dict, const ShapeContext& context) {
  const PointList list = readPoints(dict, "points", context);
  if (auto problem = polylineProblem(list.points))
    shapeError(list, "invalid polyline in " + dict.name(), *problem);
  return std::make_unique<WallSurface>(Polyline(list.points, false), "polyline");
}

std::unique_ptr<WallSurface> readBoxWall(const Dictionary& dict, const ShapeContext&) {
  const Vec2 lo = readPoint2D(dict, "min");
  const Vec2 hi = readPoint2D(dict, "max");
  if (!(hi.x() > lo.x() && hi.y() > lo.y())) {
    fatalIOError(
        dict.findEntry("max")->location(),
        fmt::format(
            "keyword 'max' in dictionary {}: max ({} {}) must exceed min ({} {}) in x and in y",
            dict.name(), hi.x(), hi.y(), lo.x(), lo.y()));
  }
  return solidBoundary(Box(lo, hi).corners(), "box");
}

std::unique_ptr<WallSurface> readPolygonWall(const Dictionary& dict, const ShapeContext& context) {
  const PointList list = readPoints(dict, "points", context);
  if (auto problem = polygonProblem(list.points))
    shapeError(list, "invalid polygon in " + dict.name(), *problem);
  return solidBoundary(Polygon(list.points).vertices(), "polygon");
}

const bool registered = WallRegistry::add("polyline", readPolylineWall) &&
                        WallRegistry::add("box", readBoxWall) &&
                        WallRegistry::add("polygon", readPolygonWall);

}  // namespace

}  // namespace isph
