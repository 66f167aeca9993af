#pragma once
// A scene to fill with particles: the lattice, material regions, walls and initial state, as
// system/particleMeshDict describes it (see SceneReader.hpp) or as code builds it (tests,
// benchmarks). Coordinates are those of the scene frame; `transform` maps them to the case.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "geometry/Region.hpp"
#include "geometry/Transform.hpp"
#include "particleGeneration/Lattice.hpp"
#include "particleGeneration/WallSurface.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

enum class InitialPressure { zero, lithostatic };
enum class MaterialSide { left, right, automatic };

// `zRange (z0 z1);` of a region in a 3D scene: the region is present in the layers whose
// z = (k + 1/2) dx lies in [z0, z1] (ZSlabs.hpp); absent, it spans the width.
struct ZRange {
  double lo = 0, hi = 0;  // [m]
  SourceLocation where;   // the zRange entry
  bool contains(double z) const { return z >= lo && z <= hi; }
};

struct RegionSpec {
  std::string name;
  std::unique_ptr<Region> shape;
  label material = 0;                   // index into Scene::materials
  double density = 0;                   // rho of that material [kg/m³]
  Vec3 initialVelocity = Vec3::Zero();  // scene frame
  std::optional<ZRange> zRange;         // 3D: part of the width only
  SourceLocation where;                 // the region's entry (for errors)
};

struct WallSpec {
  std::string name;
  std::unique_ptr<WallSurface> surface;
  label patch = 0;                         // index into Scene::patches
  MaterialSide side = MaterialSide::left;  // open polylines only; closed ones have it outside
  double density = 0;                      // mass of a wall or dummy particle = density dx²
  SourceLocation where;
};

// `dimension 3;`: walls at z = 0 and z = width (`sideWalls` in particleMeshDict), the ends of
// the extruded scene (Extrusion.hpp).
struct SideWallSpec {
  label patch[2] = {0, 0};  // indices into Scene::patches: the wall at z = 0, at z = width
  double density = 0;    // mass of a wall or dummy particle = density dx³
  // The part of the x-y section they cover (`min (x y 0); max (x y 0);`): the section's
  // bounding box clipped to it (default: no clip). A flume's 3 m catch wall made its side walls
  // 3 m high, 24 times the sand's particles.
  Vec2 min = Vec2::Constant(-1e300), max = Vec2::Constant(1e300);
  SourceLocation where;  // the sideWalls entry
};

struct Scene {
  double spacing = 0;  // dx [m]
  double maxParticles = 1e7;  // refused above (ParticleEstimate.hpp): a spacing typo, not a scene
  SourceLocation spacingWhere, maxParticlesWhere;  // the entries (for errors); unknown if built by code
  std::string cloudName = "particles";
  int dimension = 2;  // 3: the x-y scene extruded along z over 0 <= z <= width (Extrusion.hpp)
  double width = 0;   // 3D: the extent in z [m] (whole spacings: round(width / dx) layers)
  std::optional<SideWallSpec> sideWalls;  // 3D: walls closing the ends z = 0 and z = width
  LatticeType lattice = LatticeType::square;
  Vec2 latticeOrigin = Vec2::Zero();
  int wallLayers = 3;          // wall layer + dummy layers
  double wallClearance = 0.5;  // material sites closer than this × dx to a wall surface are removed
  InitialPressure initialPressure = InitialPressure::zero;
  Vec3 gravity = Vec3::Zero();  // case frame (constant/g); needed for lithostatic pressure
  Transform transform;          // scene frame -> case frame

  std::vector<std::string> materials;  // material labels (constant/materialProperties order)
  std::vector<PatchInfo> patches;      // patch labels
  std::vector<RegionSpec> regions;     // first listed wins where they overlap
  std::vector<WallSpec> walls;
};

}  // namespace isph
