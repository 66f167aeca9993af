#pragma once
// The particles that represent solid walls (Shao & Lo 2003, as the paper): one layer of wall
// particles ON the surface, carrying the unit normal that points into the material side, and
// dummy layers behind it, dx apart, `layers` layers in all so that the kernel support of a
// material particle at the wall is full.
//
// Layer k (k = 0 .. layers-1) is the curve at depth k·dx behind the surface, sampled at about
// dx: each segment of the chain is offset by k·dx into the solid and split into
// round(length/dx) equal parts, so its end points (the corners) always carry a particle.
// Corners:
//  - where the surface turns towards the material (a concave corner seen from the material,
//    e.g. a flume's bed meeting its back wall), the offset segments part: the gap is filled
//    with particles on the arc of radius k·dx about the corner, about dx apart;
//  - where it turns away (a convex corner, e.g. the top of a barrier), the offset segments are
//    cut where they meet (on the corner's bisector), and that point carries one particle; at a
//    sharp corner the thin solid between there and the corner is filled along the bisector.
// The wall particle at a corner gets the mean of its two segments' normals.
// Then, in order of layer, wall and position along the chain, a candidate is dropped when it
//  - lies closer than (k - 1/2) dx to its own surface (it belongs to a shallower layer of
//    another part: thin solids, short segments),
//  - lies on or behind the surface of an EARLIER wall, within that wall's layers (a barrier
//    standing on a bed: the bed's particles represent the contact),
//  - lies closer than dx/2 to a particle already kept (no duplicates where walls meet);
// and a wall particle whose normal points into another wall's solid (probe dx/2 along it)
// becomes a dummy (the bed under a barrier is not a surface the material can touch).
// Last, a dummy with no wall particle within (layers + 1/2) dx is dropped: under the middle of
// a barrier's foot wider than twice the layers, it is out of every material particle's
// support (which reaches layers·dx at most, dx/2 past a wall particle on the surface it
// crosses), and a dummy takes its pressure from a wall particle near it.
#include <vector>

#include "particleGeneration/WallSurface.hpp"

namespace isph {

struct WallParticle {
  Vec2 position;
  Vec2 normal = Vec2::Zero();  // wall particles: unit, into the material; dummies: zero
  int wall = 0;                // index into the walls given
  int layer = 0;               // 0: on the surface
  bool isWall = false;         // kind wall (else dummy)
};

struct WallLayerStats {
  long wallParticles = 0, dummyParticles = 0;
  long demoted = 0;  // surface particles covered by another wall (kept as dummies)
  long dropped = 0;  // candidates dropped as duplicates, inside another wall's layers, or
                     // demoted beyond the reach of every wall particle
  double surfaceLength = 0;
  double minSpacing = 0, maxSpacing = 0;  // of the wall particles along the surface
};

struct WallLayerResult {
  std::vector<WallParticle> particles;  // grouped by wall, then layer, then along the chain
  std::vector<WallLayerStats> stats;    // per wall
};

WallLayerResult generateWallLayers(const std::vector<WallSurface>& walls, int layers, double dx);

}  // namespace isph
