#pragma once
// Which side of the walls a point is on, from the wall particles alone (their positions and
// outward normals, as particleMesh writes them): the material side, behind a wall (in the
// solid), or past the open end of a wall on its solid side. particleMesh refuses material
// particles that are not on the material side; the solver refuses, at start, material particles
// behind a wall (a particle past an open end may have flowed off a wall's end).
//
// The test: the nearest wall particle w (a PointTree over the wall particles) and the wall
// particles within 1.6 dx of it (its neighbours along the wall). The depth is (x - x_w)·n_w,
// positive on the material side. Two subtleties:
//  - a corner (the neighbours' normals differ): each neighbour p meets w in a wedge, when each
//    lies in front of the other ((x_p - x_w)·(n_w - n_p) > 0.1 dx: a tank's corner, where the
//    material is in front of both), or at a solid's corner (the edge of a block, where in
//    front of either is enough). The depth is the largest of w's and its solid-corner
//    neighbours', capped by the smallest of its wedge neighbours'. In 3D both meet at one
//    point: the top of a block beside a side wall (a wedge) at the block's edge (a solid's
//    corner); one rule for the whole neighbourhood took the block's side face for a wedge and
//    put the water above the block behind it. With the corner particle's normal alone, a
//    point below the tank's bed beside its corner was taken for water;
//  - an open end (one neighbour, or all on one side with the same normal): a point behind
//    the end particle's half-plane and past the end along the wall is `pastOpenEnd`.
// A point counts as on the solid side when its depth is below -0.1 dx (wall particles sample
// the surface every dx; particleMesh keeps material at least wallClearance from it).
#include <vector>

#include "core/Types.hpp"
#include "geometry/PointTree.hpp"

namespace isph {

struct ParticleCloud;

class MaterialSideOfWalls {
 public:
  struct WallPoint {
    Vec3 position = Vec3::Zero();
    Vec3 normal = Vec3::Zero();  // outward: towards the material
    label patch = -1;
  };
  enum class Side { material, behindWall, pastOpenEnd };
  struct Verdict {
    Side side = Side::material;
    long wall = -1;     // the nearest wall particle (index into walls()); -1 without walls
    double depth = 0;   // [m], negative on the solid side
  };

  MaterialSideOfWalls(std::vector<WallPoint> walls, double dx);
  // The wall particles (kind wall) of a cloud; dx its spacing.
  static MaterialSideOfWalls ofCloud(const ParticleCloud& cloud);

  Verdict classify(const Vec3& x) const;
  bool empty() const { return walls_.empty(); }
  const std::vector<WallPoint>& walls() const { return walls_; }
  double tolerance() const { return 0.1 * dx_; }

 private:
  std::vector<WallPoint> walls_;
  double dx_;
  PointTree tree_;
};

}  // namespace isph
