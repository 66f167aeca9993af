#pragma once
// What the shape readers of particleMeshDict share: the case (CSV files are relative to it),
// point lists given inline or from a CSV file, and errors that blame a point by its line.
#include <filesystem>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "geometry/ShapeChecks.hpp"
#include "geometry/Vec2.hpp"

namespace isph {

class Dictionary;

struct ShapeContext {
  std::filesystem::path caseDir;
};

struct PointList {
  std::vector<Vec2> points;
  std::vector<SourceLocation> where;  // each point's line: its CSV line or the dictionary entry
  SourceLocation keyword;             // the entry that gave the points
  std::string keywordName;            // "points" or "pointsFile"
};

// Whether `key` or `keyFile` is present.
bool hasPoints(const Dictionary& dict, const std::string& key);

// Points written inline, `key ((x y 0) (x y 0) ...);` (z must be 0: shapes are drawn in x-y), or read
// from a CSV file, `keyFile "constant/ground.csv";` (relative to the case). Exactly one of
// the two must be given.
PointList readPoints(const Dictionary& dict, const std::string& key, const ShapeContext& context);

// A FatalIOError for `problem`, at the offending point's line when known.
[[noreturn]] void shapeError(const PointList& list, const std::string& what,
                             const ShapeProblem& problem);

// A 2D point from a dictionary vector; FatalIOError at the keyword when z is not 0.
Vec2 readPoint2D(const Dictionary& dict, const std::string& key);

}  // namespace isph
