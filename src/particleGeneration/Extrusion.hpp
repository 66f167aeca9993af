#pragma once
// A 3D scene (`dimension 3;`) is its x-y scene extruded along z over 0 <= z <= width: every
// material site and every wall and dummy particle of the x-y section is repeated in
// n = round(width / dx) layers at z = (k + 1/2) dx, k = 0 .. n-1, so that a box region of the
// section fills whole cubic cells and a wall (a plane, now) carries a particle per dx² of its
// surface. The ends z = 0 and z = n dx are open (the material leaves there) unless the scene
// has `sideWalls`: then each end is a plane wall, its `wallLayers` layers at z = -m dx and
// n dx + m dx (m = 0 .. layers-1) on the x-y lattice of the material sites, over the section's
// bounding box (material, walls and dummies: what the walls enclose; clipped to the side
// walls' `min`/`max` when given: SideWallSpec). At a side wall's layer
// m = 0 a site is a wall particle with its normal along ±z into the material, except where the
// section's walls make it solid (inside a box wall, behind a bed, beside a tank's corner: the
// section's wall particles tell, MaterialSideOfWalls.hpp): there the material cannot touch it
// from the side, so it is a dummy, as a 2D wall particle covered by another wall is
// (WallLayers.hpp); such sites deeper than (layers - 1/2) dx into the solid are dropped (out of
// every material particle's support).
#include <vector>

#include "particleGeneration/Scene.hpp"
#include "particleGeneration/WallLayers.hpp"

namespace isph {

// The z of the section's copies: {0} for a 2D scene, (k + 1/2) dx for a 3D one.
std::vector<double> extrusionLayers(const Scene& scene);

// What one particle of the section stands for along z: 1 (per metre of width) in 2D, dx in 3D.
double extrusionDepth(const Scene& scene);

struct SideWallParticle {
  Vec3 position;                // scene frame
  Vec3 normal = Vec3::Zero();   // wall particles: ±z, into the material; dummies: zero
  bool isWall = false;
  int end = 0;                  // 0: the wall at z = 0; 1: at z = width
};

// The particles of both side walls, by end (z = 0 first), layer, then row and column of the
// lattice; none unless the scene has sideWalls. `section` bounds the section's particles (scene
// frame); `walls` are the section's wall and dummy particles (WallLayers.hpp).
std::vector<SideWallParticle> sideWallParticles(const Scene& scene, const BoundingBox& section,
                                                const std::vector<WallParticle>& walls);

}  // namespace isph
