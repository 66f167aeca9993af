// The region types of particleMeshDict, registered by name:
//   box     { min (x y 0); max (x y 0); }
//   polygon { points ((x y 0) ...); }            or pointsFile "constant/area.csv";
//   profile { upper (...); lower (...); }        or upperFile/lowerFile; optional thickness
//   cylinder { base (x y z); radius R; height H; }  3D only: vertical axis (along y) through
//                                                the base's centre (Cylinder.hpp)
#include <fmt/format.h>

#include "core/Registry.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "geometry/Box.hpp"
#include "geometry/Cylinder.hpp"
#include "geometry/Polygon.hpp"
#include "geometry/Profile.hpp"
#include "particleGeneration/ShapeInput.hpp"

namespace isph {

namespace {

using RegionRegistry = Registry<Region, const Dictionary&, const ShapeContext&>;

std::unique_ptr<Region> readBox(const Dictionary& dict, const ShapeContext&) {
  const Vec2 lo = readPoint2D(dict, "min");
  const Vec2 hi = readPoint2D(dict, "max");
  if (!(hi.x() > lo.x() && hi.y() > lo.y())) {
    fatalIOError(dict.findEntry("max")->location(),
                 fmt::format("keyword 'max' in dictionary {}: max ({} {}) must exceed min ({} {}) "
                             "in x and in y (a box "
                             "with zero area)",
                             dict.name(), hi.x(), hi.y(), lo.x(), lo.y()));
  }
  return std::make_unique<Box>(lo, hi);
}

std::unique_ptr<Region> readPolygon(const Dictionary& dict, const ShapeContext& context) {
  const PointList list = readPoints(dict, "points", context);
  if (auto problem = polygonProblem(list.points))
    shapeError(list, "invalid polygon in " + dict.name(), *problem);
  return std::make_unique<Polygon>(list.points);
}

std::unique_ptr<Region> readProfile(const Dictionary& dict, const ShapeContext& context) {
  const std::optional<double> thickness = dict.getOptional<double>("thickness");
  if (thickness && !(*thickness > 0)) {
    fatalIOError(dict.findEntry("thickness")->location(),
                 fmt::format("keyword 'thickness' in dictionary {}: must be positive, found {}",
                             dict.name(), *thickness));
  }
  const PointList lower = readPoints(dict, "lower", context);
  if (auto problem = profileCurveProblem(lower.points))
    shapeError(lower, "invalid lower profile in " + dict.name(), *problem);
  PointList upper;
  if (!thickness || hasPoints(dict, "upper")) {
    upper = readPoints(dict, "upper", context);
    if (auto problem = profileCurveProblem(upper.points)) {
      shapeError(upper, "invalid upper profile in " + dict.name(), *problem);
    }
    if (auto problem = profileBandProblem(upper.points, lower.points)) {
      fatalIOError(upper.keyword,
                   fmt::format("invalid profile in {}: {}", dict.name(), problem->message));
    }
  }
  return std::make_unique<Profile>(upper.points, lower.points, thickness);
}

std::unique_ptr<Region> readCylinder(const Dictionary& dict, const ShapeContext&) {
  const Vec3 base = dict.get<Vec3>("base");
  for (const char* key : {"radius", "height"}) {
    if (!(dict.get<double>(key) > 0)) {
      fatalIOError(dict.findEntry(key)->location(),
                   fmt::format("keyword '{}' in dictionary {}: must be positive, found {}", key, dict.name(),
                               dict.get<double>(key)));
    }
  }
  return std::make_unique<Cylinder>(base, dict.get<double>("radius"), dict.get<double>("height"));
}

const bool registered = RegionRegistry::add("box", readBox) &&
                        RegionRegistry::add("cylinder", readCylinder) &&
                        RegionRegistry::add("polygon", readPolygon) &&
                        RegionRegistry::add("profile", readProfile);

}  // namespace

}  // namespace isph
