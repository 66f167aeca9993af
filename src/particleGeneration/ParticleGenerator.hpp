#pragma once
// particleMesh's work: a scene in, the initial particle cloud and what the log reports out.
//  1. fill the regions with lattice sites (first listed wins where they overlap),
//  2. put each wall's material side on its left (materialSide, or auto: probe the regions),
//  3. wall and dummy layers along every wall,
//  4. remove material sites inside solids or within the clearance of a wall surface,
//  5. a 3D scene: the section repeated along z, and its side walls (Extrusion.hpp); a region
//     with zRange only in its layers (ZSlabs.hpp: steps 1 and 4 per slab of layers),
//  6. fields: origId 0..N-1 (material by region, then walls, then side walls), mass = ρ × site
//     area (walls ρ_wall dx²; in 3D times dx), U, kind, material, patch, normal, the initial
//     pressure (lithostatic along g), all transformed from the scene frame to the case frame.
#include <string>
#include <utility>
#include <vector>

#include "geometry/BoundingBox.hpp"
#include "particleGeneration/Scene.hpp"
#include "particleGeneration/WallLayers.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

struct RegionReport {
  std::string name, type, material;
  double density = 0;
  long inside = 0;                                   // lattice sites inside the region
  std::vector<std::pair<std::string, long>> lostTo;  // to earlier regions (non-zero only)
  long inSolid = 0, nearWall = 0;                    // removed by walls
  long particles = 0;
  double geometricArea = 0, particleArea = 0;  // [m²] per unit width; 3D: volumes [m³]
  double mass = 0;                             // [kg] per unit width; 3D: [kg]
  BoundingBox bounds;                          // of its particles, case frame
};

struct WallReport {
  std::string name, patch, type, side;
  double frictionAngle = 0;
  WallLayerStats stats;
  BoundingBox bounds;  // case frame
};

struct GenerationResult {
  ParticleCloud cloud;
  std::vector<RegionReport> regions;
  std::vector<WallReport> walls;
  double closestPair = 0;        // smallest distance between two particles [m]
  std::string closestPairKinds;  // "material-wall", ...
};

GenerationResult generateParticles(const Scene& scene);

}  // namespace isph
