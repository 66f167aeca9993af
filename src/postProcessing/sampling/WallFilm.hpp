#pragma once
// The material at rest in a thin film on walls steeper than their friction angle (issue 55).
// A Coulomb wall of friction angle δ holds a layer lying on it only where the wall is inclined
// less than δ to the horizontal; on a steeper wall the layer stays only where material below
// it carries it, as the deposit in a corner. A film a particle or two thick on a steep wall
// has nothing to carry it (its stress along the wall is bounded by its confinement, which is
// its own thin weight): at rest there, it is held by the method, not by the physics.
//
// A material particle i counts when
//   - it is at rest: |u_i| < restSpeed;
//   - its nearest wall particle w (kind wall, within maxThickness) lies on a steep wall: the
//     angle between w's normal n_w (into the material) and up, −g/|g|, exceeds the friction
//     angle of w's patch (a frictionless patch: any wall not level);
//   - the material over the wall there is thin: of the material particles j whose centres lie
//     within half a spacing of the line x_i + s n_w, the farthest from the wall reaches
//     t = max_j (x_j − x_w)·n_w + dx/2 ≤ maxThickness (each particle stands for the cell
//     around it; wall particles lie on the wall's surface, so a film of one row is one
//     spacing thick and one of two rows two).
// A thick deposit against a steep wall is carried by the material below it and does not
// count; neither does material sliding (however slowly above restSpeed) or on a wall no
// steeper than its friction angle.
#include <vector>

#include "core/Types.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

struct WallFilmSpec {
  Vec3 g = Vec3(0, -9.81, 0);  // gravity (constant/g): sets up and the walls' inclination
  double restSpeed = 0.01;     // [m/s] below this a particle is at rest
  double maxThickness = 2.5;   // [spacings] a film: at most this thick normal to its wall
};

struct WallFilm {
  long particles = 0;      // material particles counted
  double mass = 0.0;       // their mass [kg] (per metre of width in 2D, as the cloud's mass)
  double lowest = 0.0;     // the lowest and the highest of them along up, x·(−g/|g|) [m]
  double highest = 0.0;    // (both 0 when none counts)
  long resting = 0;        // material particles at rest, counted or not
  std::vector<int> members;  // the counted particles (indices into the cloud), in cloud order
};

// FatalError for a zero gravity, a non-positive spacing, restSpeed or maxThickness.
WallFilm restingWallFilm(const ParticleCloud& cloud, const WallFilmSpec& spec);

}  // namespace isph
