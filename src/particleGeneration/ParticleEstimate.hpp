#pragma once
// How many particles a scene will make and the memory they will need, from its geometry
// alone, before any of them is allocated: particleMesh refuses a scene above `maxParticles`
// (system/particleMeshDict, default 10 million) with the count, the memory and what to change,
// instead of running out of memory (a spacing of 1e-10 m asked for 1e19 particles).
//
//   material   Σ over the regions of area / site area (what the lattice fills)
//   tested     Σ over the regions of the lattice sites in their bounding boxes (what the
//              filling tests one by one: a thin slanted region tests many more than it fills)
//   walls      Σ over the walls of length / dx × layers
//   3D         each of these times the layers along z, and the side walls over the walls' box
//
// Memory: particleMesh's own about 300 bytes per particle (the cloud's fields and the
// generation's temporaries); the solver's 2.4-4.6 KB per particle as the scaling benchmark
// measured it (tutorials/benchmarks/scaling/README.md: the dam break and the column collapse
// at 640k particles).
#include "core/Error.hpp"
#include "particleGeneration/Scene.hpp"

namespace isph {

struct ParticleEstimate {
  double material = 0;  // material particles
  double tested = 0;    // lattice sites the region filling tests
  double walls = 0;     // wall and dummy particles

  static constexpr double generationBytesPerParticle = 300;
  static constexpr double solverBytesPerParticle[2] = {2.4e3, 4.6e3};  // fluid, granular

  double particles() const { return material + walls; }
  double generationBytes() const { return particles() * generationBytesPerParticle; }
};

ParticleEstimate estimateParticles(const Scene& scene);

// FatalError at the scene's `maxParticles` entry (or its spacing) when the estimate exceeds
// the limit, naming the count, the memory and what to change.
void checkParticleEstimate(const Scene& scene, const ParticleEstimate& estimate);

}  // namespace isph
