#include "particleGeneration/MaterialInsideWalls.hpp"

#include <fmt/format.h>

#include <map>

#include "core/Strings.hpp"
#include "particles/MaterialSideOfWalls.hpp"

namespace isph {

namespace {

struct Outside {
  std::map<std::pair<std::string, bool>, long> perPatch;  // (patch, past its open end) -> count
  long count = 0;
  std::size_t example = 0;  // a cloud index
  MaterialSideOfWalls::Verdict verdict;
};

}  // namespace

void checkMaterialInsideWalls(const Scene& scene, const GenerationResult& result) {
  const ParticleCloud& cloud = result.cloud;
  const MaterialSideOfWalls sides = MaterialSideOfWalls::ofCloud(cloud);
  if (sides.empty()) return;
  std::vector<Outside> outside(result.regions.size());
  std::size_t a = 0;  // material particles come first, by region
  for (std::size_t r = 0; r < result.regions.size(); ++r) {
    const std::size_t end = a + static_cast<std::size_t>(result.regions[r].particles);
    for (; a < end; ++a) {
      const auto v = sides.classify(cloud.positions[a]);
      if (v.side == MaterialSideOfWalls::Side::material) continue;
      const auto& wall = sides.walls()[static_cast<std::size_t>(v.wall)];
      const std::string patch = cloud.properties.patches.at(static_cast<std::size_t>(wall.patch)).name;
      Outside& o = outside[r];
      if (o.count++ == 0) o.example = a, o.verdict = v;
      ++o.perPatch[{patch, v.side == MaterialSideOfWalls::Side::pastOpenEnd}];
    }
  }
  long total = 0;
  for (const auto& o : outside) total += o.count;
  if (total == 0) return;
  for (std::size_t r = 0; r < outside.size(); ++r) {
    const Outside& o = outside[r];
    if (o.count == 0) continue;
    std::vector<std::string> counts;
    for (const auto& [key, n] : o.perPatch) {
      counts.push_back(fmt::format("{} {} patch '{}'", n, key.second ? "past the open end of" : "behind", key.first));
    }
    const Vec3& x = cloud.positions[o.example];
    const auto& wall = sides.walls()[static_cast<std::size_t>(o.verdict.wall)];
    fatalIOError(
        scene.regions[r].where,
        fmt::format(
            "region '{}' puts {} of its {} material particles outside the walls: {}{} (e.g. at ({:.6g} {:.6g} "
            "{:.6g}), {:.4g} m on the solid side of the wall particle at ({:.6g} {:.6g} {:.6g}) of patch '{}'). The "
            "solver would run them there.\n    Make the region end on the walls' material side (a region drawn "
            "across a wall loses the sites behind it, but not those beside its corners and ends), and check each "
            "wall's materialSide (left: on the left walking from its first point to its last)",
            scene.regions[r].name, o.count, result.regions[r].particles, join(counts, ", "),
            total > o.count ? fmt::format("; {} more in other regions", total - o.count) : std::string(), x.x(),
            x.y(), x.z(), -o.verdict.depth, wall.position.x(), wall.position.y(), wall.position.z(),
            cloud.properties.patches.at(static_cast<std::size_t>(wall.patch)).name));
  }
}

}  // namespace isph
