#include "particles/MaterialSideOfWalls.hpp"

#include <algorithm>

#include "particles/ParticleCloud.hpp"
#include "particles/ParticleKind.hpp"

namespace isph {

namespace {

std::vector<Vec3> positionsOf(const std::vector<MaterialSideOfWalls::WallPoint>& walls) {
  std::vector<Vec3> x;
  x.reserve(walls.size());
  for (const auto& w : walls) x.push_back(w.position);
  return x;
}

constexpr double neighbourReach = 1.6;  // [dx]: a wall particle's neighbours along its wall
constexpr double sameNormal = 0.9999;   // cosine above which two normals are one direction

}  // namespace

MaterialSideOfWalls::MaterialSideOfWalls(std::vector<WallPoint> walls, double dx)
    : walls_(std::move(walls)), dx_(dx), tree_(positionsOf(walls_)) {}

MaterialSideOfWalls MaterialSideOfWalls::ofCloud(const ParticleCloud& cloud) {
  std::vector<WallPoint> walls;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != static_cast<label>(ParticleKind::wall)) continue;
    walls.push_back({cloud.positions[i], cloud.normal[i], cloud.patch[i]});
  }
  return MaterialSideOfWalls(std::move(walls), cloud.properties.spacing);
}

MaterialSideOfWalls::Verdict MaterialSideOfWalls::classify(const Vec3& x) const {
  Verdict v;
  v.wall = tree_.nearest(x);
  if (v.wall < 0) return v;
  const WallPoint& w = walls_[static_cast<std::size_t>(v.wall)];
  v.depth = (x - w.position).dot(w.normal);

  std::vector<long> around = tree_.within(w.position, neighbourReach * dx_);
  std::erase(around, v.wall);
  // The most different normals among w and its neighbours.
  double lowest = 1;
  around.push_back(v.wall);
  for (std::size_t i = 0; i < around.size(); ++i) {
    for (std::size_t j = i + 1; j < around.size(); ++j) {
      lowest = std::min(lowest, walls_[static_cast<std::size_t>(around[i])].normal.dot(
                                    walls_[static_cast<std::size_t>(around[j])].normal));
    }
  }
  around.pop_back();

  if (lowest > sameNormal) {  // a straight stretch, or an open end
    bool end = true;          // every neighbour on one side of w along the wall
    for (std::size_t i = 0; i < around.size() && end; ++i) {
      for (std::size_t j = i + 1; j < around.size() && end; ++j) {
        end = (walls_[static_cast<std::size_t>(around[i])].position - w.position)
                  .dot(walls_[static_cast<std::size_t>(around[j])].position - w.position) > 0;
      }
    }
    if (v.depth >= -tolerance()) return v;
    v.side = Side::behindWall;
    if (end) {
      Vec3 along = Vec3::Zero();  // from w towards its neighbours
      for (long n : around) along += walls_[static_cast<std::size_t>(n)].position - w.position;
      if (around.empty() || (x - w.position).dot(along) < 0) v.side = Side::pastOpenEnd;
    }
    return v;
  }

  // A corner. Each neighbour p meets w either in a wedge (each in front of the other, a tank's
  // corner: the material is in front of both) or at a solid's corner (in front of either). In
  // 3D both at once: the top of a block beside a side wall (a wedge) at the block's edge (a
  // solid's corner). So: in front of w or of a neighbour at a solid's corner with it, and in
  // front of every neighbour in a wedge with it. "In front of each other" by more than the
  // tolerance: a side wall's particle above a block's edge and the block's face particle
  // below it, dx/2 from each other's planes, are neither (exactly 0: round-off decided).
  double solidCorner = v.depth, wedge = 1e300;
  for (long n : around) {
    const WallPoint& p = walls_[static_cast<std::size_t>(n)];
    const double d = (x - p.position).dot(p.normal);
    if ((p.position - w.position).dot(w.normal - p.normal) > tolerance())
      wedge = std::min(wedge, d);
    else
      solidCorner = std::max(solidCorner, d);
  }
  const double depth = std::min(solidCorner, wedge);
  v.depth = depth;
  if (depth < -tolerance()) v.side = Side::behindWall;
  return v;
}

}  // namespace isph
