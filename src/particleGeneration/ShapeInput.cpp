#include "particleGeneration/ShapeInput.hpp"

#include <fmt/format.h>

#include "core/dictionary/Dictionary.hpp"
#include "particleGeneration/CsvPoints.hpp"

namespace isph {

bool hasPoints(const Dictionary& dict, const std::string& key) {
  return dict.found(key) || dict.found(key + "File");
}

PointList readPoints(const Dictionary& dict, const std::string& key, const ShapeContext& context) {
  const std::string fileKey = key + "File";
  const Entry* inlineEntry = dict.findEntry(key);
  const Entry* file = dict.findEntry(fileKey);
  dict.markRead(key);
  dict.markRead(fileKey);
  if (inlineEntry && file) {
    fatalIOError(file->location(),
                 fmt::format("give the points either inline ({}) or from a file ({}), not both "
                             "(dictionary {})",
                             key, fileKey, dict.name()));
  }
  PointList out;
  if (file) {
    const std::string name = dict.get<std::string>(fileKey);
    std::filesystem::path path(name);
    if (path.is_relative()) path = context.caseDir / path;
    const CsvPoints csv = readCsvPoints(path, file->location());
    const auto fileName = std::make_shared<const std::string>(path.string());
    out.points = csv.points;
    for (int line : csv.lines) out.where.push_back(SourceLocation{fileName, line, 0});
    out.keyword = file->location();
    out.keywordName = fileKey;
    return out;
  }
  if (!inlineEntry) {
    fatalIOError(dict.location(),
                 fmt::format("dictionary {} needs the points of its shape: `{} ((x y 0) ...);` or "
                             "`{} \"file.csv\";` (x,y columns, relative to the case)",
                             dict.name(), key, fileKey));
  }
  const auto points = dict.get<std::vector<Vec3>>(key);
  for (const Vec3& p : points) {
    if (p.z() != 0.0) {
      fatalIOError(inlineEntry->location(),
                   fmt::format("keyword '{}' in dictionary {}: z must be 0: shapes are drawn in the x-y plane (a 3D scene extrudes them along z), found "
                               "({} {} {})",
                               key, dict.name(), p.x(), p.y(), p.z()));
    }
    out.points.push_back(toVec2(p));
    out.where.push_back(inlineEntry->location());
  }
  out.keyword = inlineEntry->location();
  out.keywordName = key;
  return out;
}

void shapeError(const PointList& list, const std::string& what, const ShapeProblem& problem) {
  const bool known =
      problem.point >= 0 && static_cast<std::size_t>(problem.point) < list.where.size();
  const SourceLocation& where =
      known ? list.where[static_cast<std::size_t>(problem.point)] : list.keyword;
  fatalIOError(where,
               fmt::format("{} (keyword '{}'): {}", what, list.keywordName, problem.message));
}

Vec2 readPoint2D(const Dictionary& dict, const std::string& key) {
  const Vec3 p = dict.get<Vec3>(key);
  if (p.z() != 0.0) {
    fatalIOError(dict.findEntry(key)->location(),
                 fmt::format("keyword '{}' in dictionary {}: z must be 0: shapes are drawn in the x-y plane (a 3D scene extrudes them along z), found {}",
                             key, dict.name(), p.z()));
  }
  return toVec2(p);
}

}  // namespace isph
